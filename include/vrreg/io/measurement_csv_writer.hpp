// SPDX-License-Identifier: Apache-2.0
#pragma once
// Writes individual readings (not averaged) as a measurement CSV (design.md 6) in millimetres and
// radians, with numbers in the shortest text that reads back exactly; read_measurement_csv reads
// it back. Columns: point, role, robot_{x,y,z}_mm (unless no reading has a robot position),
// sensor_{x,y,z}_mm, then config, q1_rad..qN_rad, from_q1_rad..from_qN_rad, repeat, visit,
// sensor_qx..qw, robot_qx..qw when the readings carry them.
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"

namespace vrreg::io {

/// One reading: a row of a measurement CSV, in SI units.
struct Reading {
  std::string point{};  ///< label: not empty, no comma, quote, '#' start or spaces
  Role role = Role::kFiducial;
  bool has_robot = true;  ///< false: sensor-only point (all readings must agree)
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();   ///< nominal position, robot frame [m]
  Eigen::Vector3d sensor_m = Eigen::Vector3d::Zero();  ///< measured position, sensor frame [m]
  std::optional<int> config{};  ///< arm configuration label (all readings or none)
  std::vector<double> q_rad{};  ///< joint angles [rad] (same count in every reading)
  /// Joints the robot came from (from_q1_rad..; all readings or none; as many as q_rad) [rad].
  std::vector<double> from_q_rad{};
  std::optional<int> repeat{};  ///< repeat index >= 0 (all readings or none)
  std::optional<int> visit{};   ///< visit index >= 0 (all readings or none)
  /// The marker's measured orientation, sensor frame (sensor_qx..qw; all readings or none).
  std::optional<Eigen::Quaterniond> q_sensor_marker{};
  /// The marker's commanded orientation, robot frame (robot_qx..qw; all readings or none).
  std::optional<Eigen::Quaterniond> q_robot_marker{};
};

/// The CSV text: `comments` as `# ` lines first, then the header and one row per reading.
/// Throws InputError on readings that cannot be written consistently (see Reading).
std::string format_measurement_csv(const std::vector<Reading>& readings,
                                   const std::vector<std::string>& comments = {});

/// Writes format_measurement_csv(readings, comments) to `path` atomically (whole or not at all).
void write_measurement_csv(const std::string& path, const std::vector<Reading>& readings,
                           const std::vector<std::string>& comments = {});

}  // namespace vrreg::io
