// SPDX-License-Identifier: Apache-2.0
#pragma once
// The front door's input: locations measured in both frames, as arrays (one column a location).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/types.hpp"

namespace vrreg {

/// Locations measured by the sensor and commanded to the robot, one column (or entry) each.
/// Only `sensor_m` is required; every other member is empty or has one entry per location.
struct MeasuredPoints {
  Points3 sensor_m{};  ///< measured (mean) positions, sensor frame [m]
  /// Nominal (commanded) positions, robot frame [m]; needed to register and evaluate, and by
  /// octuplet correction; may have 0 columns when only correcting with grid or scattered.
  Points3 robot_m{};
  Eigen::VectorXd weights{};         ///< registration weights (Eq. 2), >= 0; empty: all equal
  std::vector<std::string> names{};  ///< labels for messages and outputs; empty: "1", "2", ...
  std::vector<int> configs{};        ///< arm configuration labels (Procedure 2); empty: none
  Eigen::MatrixXd joints_rad{};      ///< joint angles, one column per location [rad]; empty: none
  /// Per location and joint, the sign (-1, 0, +1) of the joint's last move before the location
  /// was reached (its approach direction, update_approach_sign), one column per location as
  /// joints_rad; 0 x 0 when unknown. Passed to CorrectionQuery::approach_sign.
  Eigen::MatrixXd approach_sign{};
  /// Repeat readings averaged into each sensor position, and their per-axis sums of squared
  /// deviations [m^2] (for sigma_opt, Eq. 9); both empty when unknown.
  Eigen::VectorXi n_readings{};
  Points3 sensor_sq_dev_m2{};
  /// Rigid-body markers (docs/orientation.md): the measured orientation of each location's
  /// marker, sensor frame, and the commanded one, robot frame; unit quaternions (norms within
  /// kUnitQuaternionTolerance of 1, normalised when used). Fiducials with both get an orientation
  /// field; points with a measured one get their orientation corrected. Empty: none.
  std::vector<Eigen::Quaterniond> q_sensor_marker{};
  std::vector<Eigen::Quaterniond> q_robot_marker{};

  [[nodiscard]] Eigen::Index size() const { return sensor_m.cols(); }
  /// Throws InputError naming the member when sizes disagree or a value is not finite.
  void validate(bool require_robot) const;
  /// As a measurement set of `role` locations (the library's internal record of file rows).
  [[nodiscard]] MeasurementSet to_measurement_set(Role role, bool require_robot) const;
};

}  // namespace vrreg
