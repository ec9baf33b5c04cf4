// SPDX-License-Identifier: Apache-2.0
#pragma once
// The consumer's cell, in memory [m]: 27 fiducials on a 50 mm grid and 8 targets at its cube
// centres, commanded to the robot (robot_m), seen by a camera 2 m away and turned 0.4 rad
// (sensor_m), with a smooth robot error of about 1 mm that RRBC should remove.
#include <Eigen/Geometry>
#include <string>
#include <vrreg/vrreg.hpp>

inline void sense(vrreg::MeasuredPoints& p) {
  const Eigen::ArrayXXd y = p.robot_m.array();
  const Eigen::ArrayXXd reached = y + 1e-3 * (7.0 * y.colwise().reverse()).sin();
  p.sensor_m = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
               reached.matrix();
  p.sensor_m.row(2).array() += 2.0;
}

inline vrreg::MeasuredPoints cell_fiducials() {
  vrreg::MeasuredPoints f;
  f.robot_m.resize(3, 27);
  for (int i = 0; i < 27; ++i) f.robot_m.col(i) << 0.3 + 0.05 * (i % 3), 0.05 * (i / 3 % 3), 0.2 + 0.05 * (i / 9);
  for (int i = 0; i < 27; ++i) f.names.push_back("F" + std::to_string(i + 1));
  sense(f);
  return f;
}

inline vrreg::MeasuredPoints cell_targets() {
  vrreg::MeasuredPoints t;
  t.robot_m.resize(3, 8);
  for (int i = 0; i < 8; ++i) t.robot_m.col(i) << 0.325 + 0.05 * (i % 2), 0.025 + 0.05 * (i / 2 % 2), 0.225 + 0.05 * (i / 4);
  for (int i = 0; i < 8; ++i) t.names.push_back("T" + std::to_string(i + 1));
  sense(t);
  return t;
}
