// SPDX-License-Identifier: Apache-2.0
#pragma once
// A plan as a program the robot runs to collect the data (docs/hand-eye.md): each location in
// visiting order, a joint move, a settling pause, and a stop until the tracker's readings are
// taken. URScript (Universal Robots), KRL (KUKA) or a plain joint CSV for any controller.
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/kinematics/joint_vector.hpp"

namespace vrreg::planning {

/// Program formats.
enum class ProgramFormat { kUrScript, kKrl, kJointCsv };

/// Parses "urscript", "krl" or "csv"; throws InputError otherwise.
ProgramFormat parse_program_format(const std::string& text);

/// One location as the program visits it.
struct ProgramLocation {
  std::string point{};  ///< label: the measurement CSV's `point`
  Role role = Role::kFiducial;
  std::string config{};             ///< configuration label, empty when none
  kinematics::JointVector q_rad{};  ///< commanded joints [rad]
  int visit = -1;  ///< which visit of a point read in rounds (monitor points); -1: not numbered
  /// Joints of a via point moved to just before, without a stop or readings (approach.hpp) [rad];
  /// empty: none.
  std::optional<kinematics::JointVector> via_q_rad{};
};

/// How the program moves and waits.
struct ProgramOptions {
  int repeats = 12;                ///< tracker readings per location (the measurement CSV's repeat)
  double settle_s = 1.0;           ///< pause after each move before the readings [s]
  double joint_speed_rad_s = 0.5;  ///< URScript movej v
  double joint_accel_rad_s2 = 0.8;  ///< URScript movej a
  int krl_velocity_percent = 20;    ///< KRL $VEL_AXIS for every axis
  std::string name = "vrreg_plan";  ///< program name (letters, digits, underscore)
  void validate() const;
};

/// The program text; a location's via point is a joint move of its own just before it, marked
/// "via" (no pause, no readings; the joint CSV gives it repeats 0). URScript needs 6 joints; KRL 6 (A1-A6) or 7 (LWR 4+: A1 A2 E1 A3 A4 A5 A6).
/// Throws InputError on an empty plan, non-finite joints or a joint count the format cannot take.
std::string robot_program(const std::vector<ProgramLocation>& locations, ProgramFormat format,
                          const ProgramOptions& options = {});

}  // namespace vrreg::planning
