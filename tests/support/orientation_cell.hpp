// SPDX-License-Identifier: Apache-2.0
#pragma once
// A small cell with rigid-body markers for the tests of orientations through the library's
// doors (files, arrays, the service): fiducials and targets with measured and commanded
// orientations, the marker missing its commanded orientation by a smooth field of a few mrad and
// its commanded position by one of 0.1 mm (five times the noise: a correction the guard applies).
#include <cmath>
#include <string>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/pipeline/points.hpp"

namespace vrreg::testing {

/// A 5 x 5 x 5 grid at 40 mm read by a rotated sensor (fiducials), targets at the cell centres;
/// every location has 4 readings, a random commanded orientation and the measured one.
inline MeasurementSet cell_with_orientations() {
  Random rng(31);
  const RigidTransform T_sensor_robot(rotation_exp(Eigen::Vector3d(0.2, -0.5, 1.0)),
                                      Eigen::Vector3d(0.1, 0.3, 2.0));
  MeasurementSet set;
  set.source = "cell.csv";
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k)
        for (const bool target : {false, true}) {
          if (target && (i == 4 || j == 4 || k == 4)) continue;
          Location l;
          l.point = (target ? "t" : "f") + std::to_string(25 * i + 5 * j + k);
          l.role = target ? Role::kTarget : Role::kFiducial;
          l.robot_m = Eigen::Vector3d(0.4, -0.1, 0.1) + 0.04 * Eigen::Vector3d(i, j, k) +
                      (target ? Eigen::Vector3d::Constant(0.02) : Eigen::Vector3d::Zero());
          const Eigen::Vector3d error_m(1e-4 * std::sin(10 * l.robot_m.x()),
                                        1e-4 * std::cos(12 * l.robot_m.y()),
                                        1e-4 * std::sin(9 * l.robot_m.z()));
          l.sensor_m = T_sensor_robot.apply(l.robot_m + error_m + rng.normal3(2e-5));
          l.n_readings = 4;
          l.sensor_sq_dev_m2 = Eigen::Vector3d::Constant(3 * 4e-10);
          const Eigen::Matrix3d commanded = rng.rotation();
          const Eigen::Vector3d error_rad(3e-3 * std::sin(8 * l.robot_m.x()),
                                          2e-3 * std::cos(6 * l.robot_m.y()), 1e-3);
          const Eigen::Matrix3d actual = rotation_exp(error_rad + rng.normal3(1e-4)) * commanded;
          l.q_robot_marker = Eigen::Quaterniond(commanded);
          l.q_sensor_marker = Eigen::Quaterniond(T_sensor_robot.rotation * actual);
          l.orientation_sq_dev_rad2 = 3 * 3 * 1e-8;
          l.source_line = set.locations.size() + 2;
          set.locations.push_back(l);
        }
  return set;
}

/// The `role` rows of `set` as arrays (positions, names, orientations; no repeat statistics).
inline MeasuredPoints points_of(const MeasurementSet& set, Role role) {
  const std::vector<std::size_t> rows = set.select(role, std::nullopt);
  MeasuredPoints p;
  p.sensor_m = set.sensor_points(rows);
  p.robot_m = set.robot_points(rows);
  for (const std::size_t r : rows) {
    const Location& l = set.locations[r];
    p.names.push_back(l.point);
    if (l.q_sensor_marker) p.q_sensor_marker.push_back(*l.q_sensor_marker);
    if (l.q_robot_marker) p.q_robot_marker.push_back(*l.q_robot_marker);
  }
  return p;
}

}  // namespace vrreg::testing
