// SPDX-License-Identifier: Apache-2.0
#pragma once
// A measurement set: locations measured in both frames, after averaging repeat readings.
// Plain data shared by io (which fills it) and the domain modules (which read it).
#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// What a location is used for: fiducials build the registration, targets test it, monitor
/// points are read again later to check that the registration still holds.
enum class Role { kFiducial, kTarget, kMonitor };

/// The role's name in files ("fiducial", "target", "monitor").
const char* to_string(Role role);

/// One measured location: a (point, config, visit) triple with its repeat readings averaged.
struct Location {
  std::string point{};  ///< point label from the file
  Role role = Role::kFiducial;
  std::optional<int> config{};    ///< arm configuration label, when the file has one
  /// Which visit of the point this is, when the file numbers visits: the arm left and came back,
  /// so the robot's repeatability differs between visits (monitor points are visited several
  /// times).
  std::optional<int> visit{};
  bool has_robot = true;          ///< false for points measured in the sensor frame only
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();   ///< nominal (commanded) position, robot frame
  Eigen::Vector3d sensor_m = Eigen::Vector3d::Zero();  ///< mean measured position, sensor frame
  int n_readings = 0;             ///< number of repeat readings averaged into sensor_m
  Eigen::Vector3d sensor_sq_dev_m2 = Eigen::Vector3d::Zero();  ///< per-axis sum of squared deviations
  std::vector<double> q_rad{};                                 ///< joint angles, empty when absent
  /// Per joint, the sign of the joint's last move before this reading (+1 arrived moving up,
  /// -1 moving down, 0 unknown): lost motion leaves the joint short of its command against it.
  /// Empty when the file gives neither joints nor from_q columns (docs/file-formats.md).
  std::vector<double> approach_sign{};
  /// The marker's orientation in the sensor frame (rigid-body trackers), averaged over the
  /// repeat readings; empty when the file has no sensor_qx..qw columns.
  std::optional<Eigen::Quaterniond> q_sensor_marker{};
  /// Sum over the repeat readings of the squared angle between each reading's orientation and
  /// their mean [rad^2] (the spread of q_sensor_marker; 0 with one reading or none).
  double orientation_sq_dev_rad2 = 0.0;
  /// The commanded orientation of the same marker frame in the robot frame (robot_qx..qw), or
  /// empty: with q_sensor_marker it gives the fiducial's rotation residual (correction/
  /// orientation_field.hpp).
  std::optional<Eigen::Quaterniond> q_robot_marker{};
  double weight = 1.0;            ///< registration weight (Eq. 2); files give every location 1
  std::size_t source_line = 0;    ///< first line of the file this location came from (1-based)
};

/// Where a measurement set's approach directions (Location::approach_sign) come from.
enum class ApproachSource {
  kNone,       ///< no joints: the directions are unknown
  kRowOrder,   ///< the rows' order is the visiting order: each joint's last move before the row
  kFromJoints  ///< from_q1..from_qN columns: the joints the robot came from, row by row
};

/// Updates `sign_out` (per joint -1, 0, +1) for a move from `q_from_rad` to `q_to_rad` [rad]: a
/// joint that moved takes the sign of its move; a joint that did not move keeps its sign (the
/// gear play stays taken up where the last move left it).
void update_approach_sign(const Eigen::Ref<const Eigen::VectorXd>& q_from_rad,
                          const Eigen::Ref<const Eigen::VectorXd>& q_to_rad,
                          Eigen::Ref<Eigen::VectorXd> sign_out);

/// All locations of one file, in the order of their first reading (the visiting order).
struct MeasurementSet {
  std::string source{};  ///< file name, for messages
  std::vector<Location> locations{};
  int n_joints = 0;               ///< joint columns in the file (0 when none)
  bool has_config = false;
  bool has_repeat = false;
  bool has_visit = false;
  ApproachSource approach = ApproachSource::kNone;  ///< where approach_sign came from

  /// Indices of the locations with this role and, if given, this configuration label.
  [[nodiscard]] std::vector<std::size_t> select(Role role, std::optional<int> config = {}) const;
  /// Nominal robot-frame positions of the given locations, one column each [m].
  [[nodiscard]] Points3 robot_points(const std::vector<std::size_t>& indices) const;
  /// Mean sensor-frame positions of the given locations, one column each [m].
  [[nodiscard]] Points3 sensor_points(const std::vector<std::size_t>& indices) const;
};

}  // namespace vrreg
