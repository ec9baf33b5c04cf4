// SPDX-License-Identifier: Apache-2.0
#pragma once
// `vrreg register --estimate-marker-offset --robot ROBOT`: hand-eye registration (the marker's
// offset on the flange estimated with T_robot_sensor, docs/hand-eye.md) and its report.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "robot_cli.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"

namespace vrreg::cli {

/// The flags of the marker-offset estimate.
struct MarkerOffsetFlags {
  bool estimate = false;
  std::vector<double> known_mm;  ///< --marker-offset-mm: the offset given, not estimated
  std::string robot;
  RobotLinkFlags links;  ///< --tip-link, --base-link of a URDF robot
  double min_orientation_spread = 0.02;
  double joint_offset_sigma_deg = 0.0;  ///< the robot's joint zero-offset uncertainty
  void add_to(CLI::App& command);
  /// Throws InputError when a marker-offset mode is given without --robot.
  void check() const;
  [[nodiscard]] bool enabled() const { return estimate || !known_mm.empty(); }
};

/// Reads the fiducials, estimates the offset and registers; prints the estimate (table or JSON)
/// and writes the model. An unobservable offset is an error (exit 1) that says why.
void run_register_with_marker_offset(const std::string& fiducials_path,
                                     const MarkerOffsetFlags& flags, const RegisterOptions& options,
                                     const std::string& output, bool json);

}  // namespace vrreg::cli
