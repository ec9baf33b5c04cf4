// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/points.hpp"

#include <cmath>
#include <string>

#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"

namespace vrreg {
namespace {

void check_count(Eigen::Index got, Eigen::Index n, const char* member) {
  VRREG_THROW_UNLESS(got == 0 || got == n, "points: " << member << " has " << got << " entries for "
                                                      << n << " points (give one each, or none)");
}

void check_unit(const std::vector<Eigen::Quaterniond>& q, const char* member) {
  for (std::size_t i = 0; i < q.size(); ++i) {
    const std::string what = std::string("points: ") + member + "[" + std::to_string(i) + "]";
    (void)unit_quaternion(q[i].coeffs(), what.c_str());
  }
}

}  // namespace

void MeasuredPoints::validate(bool require_robot) const {
  const Eigen::Index n = size();
  VRREG_THROW_UNLESS(n > 0, "points: no points given (sensor_m has 0 columns)");
  VRREG_THROW_UNLESS(sensor_m.allFinite(), "points: sensor_m is not all finite");
  VRREG_THROW_UNLESS(!require_robot || robot_m.cols() == n, "points: robot_m has "
                                                                << robot_m.cols() << " columns for "
                                                                << n << " sensor positions");
  check_count(robot_m.cols(), n, "robot_m");
  VRREG_THROW_UNLESS(robot_m.allFinite(), "points: robot_m is not all finite");
  check_count(weights.size(), n, "weights");
  VRREG_THROW_UNLESS(weights.allFinite() && (weights.size() == 0 || weights.minCoeff() >= 0.0),
                     "points: weights must be finite and >= 0");
  check_count(static_cast<Eigen::Index>(names.size()), n, "names");
  check_count(static_cast<Eigen::Index>(configs.size()), n, "configs");
  check_count(joints_rad.cols(), n, "joints_rad");
  VRREG_THROW_UNLESS(joints_rad.allFinite(), "points: joints_rad is not all finite");
  check_count(n_readings.size(), n, "n_readings");
  check_count(sensor_sq_dev_m2.cols(), n, "sensor_sq_dev_m2");
  VRREG_THROW_UNLESS((n_readings.size() == 0) == (sensor_sq_dev_m2.cols() == 0),
                     "points: give n_readings and sensor_sq_dev_m2 together");
  VRREG_THROW_UNLESS(n_readings.size() == 0 || n_readings.minCoeff() >= 1,
                     "points: n_readings must be >= 1");
  VRREG_THROW_UNLESS(sensor_sq_dev_m2.allFinite() &&
                         (sensor_sq_dev_m2.size() == 0 || sensor_sq_dev_m2.minCoeff() >= 0.0),
                     "points: sensor_sq_dev_m2 must be finite and >= 0");
  check_count(static_cast<Eigen::Index>(q_sensor_marker.size()), n, "q_sensor_marker");
  check_count(static_cast<Eigen::Index>(q_robot_marker.size()), n, "q_robot_marker");
  check_unit(q_sensor_marker, "q_sensor_marker");
  check_unit(q_robot_marker, "q_robot_marker");
}

MeasurementSet MeasuredPoints::to_measurement_set(Role role, bool require_robot) const {
  validate(require_robot);
  MeasurementSet set;
  const Eigen::Index n = size();
  set.n_joints = static_cast<int>(joints_rad.cols() > 0 ? joints_rad.rows() : 0);
  set.has_config = !configs.empty();
  set.has_repeat = n_readings.size() > 0;
  set.locations.resize(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    Location& loc = set.locations[static_cast<std::size_t>(i)];
    loc.point = names.empty() ? std::to_string(i + 1) : names[static_cast<std::size_t>(i)];
    loc.role = role;
    if (!configs.empty()) loc.config = configs[static_cast<std::size_t>(i)];
    loc.has_robot = robot_m.cols() > 0;
    if (loc.has_robot) loc.robot_m = robot_m.col(i);
    loc.sensor_m = sensor_m.col(i);
    loc.n_readings = n_readings.size() > 0 ? n_readings(i) : 1;
    if (sensor_sq_dev_m2.cols() > 0) loc.sensor_sq_dev_m2 = sensor_sq_dev_m2.col(i);
    if (joints_rad.cols() > 0) {
      loc.q_rad.assign(joints_rad.col(i).data(), joints_rad.col(i).data() + joints_rad.rows());
    }
    if (approach_sign.cols() == sensor_m.cols() && approach_sign.rows() == joints_rad.rows() &&
        joints_rad.cols() > 0) {
      loc.approach_sign.assign(approach_sign.col(i).data(),
                               approach_sign.col(i).data() + approach_sign.rows());
    }
    if (weights.size() > 0) loc.weight = weights(i);
    const auto k = static_cast<std::size_t>(i);
    if (!q_sensor_marker.empty()) {
      loc.q_sensor_marker = unit_quaternion(q_sensor_marker[k].coeffs(), "q_sensor_marker");
    }
    if (!q_robot_marker.empty()) {
      loc.q_robot_marker = unit_quaternion(q_robot_marker[k].coeffs(), "q_robot_marker");
    }
  }
  return set;
}

}  // namespace vrreg
