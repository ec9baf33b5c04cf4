// SPDX-License-Identifier: Apache-2.0
#pragma once
// One data row of a measurement CSV, parsed and converted to SI units.
#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "measurement_header.hpp"
#include "vrreg/core/measurement.hpp"
#include "vrreg/core/rotation.hpp"

namespace vrreg::io::detail {

/// A reading as it appears on one row, in metres and radians; `point` views the line buffer.
struct MeasurementRow {
  std::string_view point;
  Role role = Role::kFiducial;
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d sensor_m = Eigen::Vector3d::Zero();
  std::optional<int> config;
  std::vector<double> q_rad;
  std::vector<double> from_q_rad;     ///< the joints the robot came from, when the file has them
  std::vector<double> approach_sign;  ///< per joint -1, 0, +1; set by the reader (Location)
  std::optional<int> repeat;
  std::optional<int> visit;
  std::optional<Eigen::Quaterniond> q_sensor_marker;  ///< normalised, when the file has it
  std::optional<Eigen::Quaterniond> q_robot_marker;   ///< commanded, normalised, when given
};

/// A quaternion read from a file is accepted when its norm is within this of 1, then normalised.
inline constexpr double kQuaternionNormTolerance = kUnitQuaternionTolerance;

/// Parses the trimmed `fields` of line `line` into `row`; throws FileError on any bad value.
void parse_measurement_row(const std::vector<std::string_view>& fields,
                           const MeasurementColumns& columns, const std::string& source,
                           std::size_t line, MeasurementRow& row);

}  // namespace vrreg::io::detail
