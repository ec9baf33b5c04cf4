// SPDX-License-Identifier: Apache-2.0
#pragma once
// `vrreg plan` output: the plan CSV rows and comment header, the summary and its JSON form.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "robot_cli.hpp"
#include "vrreg/io/plan_csv.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/planning/plan.hpp"

namespace vrreg::cli {

/// Command-line arguments of `vrreg plan`.
struct PlanArgs {
  std::string parts;
  double halfwidth_mm = 0.0;
  double spacing_mm = 0.0;
  std::string robot;
  RobotLinkFlags links;  ///< --tip-link, --base-link of a URDF robot
  std::optional<double> sigma_noise_mm;
  bool force = false;
  std::vector<double> tool_mm;
  std::vector<double> rpy_deg;
  std::optional<double> psi_deg;
  std::vector<double> home_deg;
  std::string norm = "l2";
  std::optional<double> offset_tilt_deg;  ///< tilt the locations so the marker offset is observable
  std::string export_format;              ///< robot program: urscript, krl or csv
  std::string program;                    ///< where to write it
  int repeats = 0;                        ///< tracker readings per location the program waits for
  int monitor = 0;                        ///< monitor points to add (0: none)
  int monitor_visits = 12;                ///< visits of each monitor point per reading
  std::string monitor_program;            ///< the check's program (monitor points only)
  std::string approach_from;  ///< "+", "-" or one sign per joint: via points before every location
  double approach_offset_deg = 2.0;  ///< the via points' offset per joint
  std::string output;
  bool json = false;
};

/// The robot, part points and options a plan was made with, and where the defaults came from.
struct PlanSetup {
  kinematics::SerialChain chain;
  std::vector<planning::PartPoint> parts;
  planning::PlanOptions options;
  std::vector<std::string> notes;  ///< e.g. "tool orientation: the simulated ur5 test bed's"
};

/// The robot (tool offset defaulted from the test bed) and the planning options of `args`, with
/// notes on where the defaults came from; the part points are left empty.
PlanSetup make_plan_setup(const PlanArgs& args);

/// Plan locations as plan CSV rows (visiting order).
std::vector<io::PlanRow> plan_rows(const planning::PlanResult& plan);

/// The comment header of the plan CSV: every parameter, "key: value" per line.
std::vector<std::string> plan_comments(const PlanArgs& args, const PlanSetup& setup,
                                       const planning::PlanResult& plan);

/// The summary as one JSON object (lengths in mm, angles in deg).
nlohmann::json plan_json(const PlanArgs& args, const PlanSetup& setup,
                         const planning::PlanResult& plan);

/// Prints the human summary (mm) to stdout.
void print_plan_summary(const PlanArgs& args, const PlanSetup& setup,
                        const planning::PlanResult& plan);

}  // namespace vrreg::cli
