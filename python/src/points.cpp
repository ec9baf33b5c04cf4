// SPDX-License-Identifier: Apache-2.0
#include "points.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>

#include "arrays.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/measurement.hpp"
#include "vrreg/core/rotation.hpp"

namespace vrreg::python {
namespace {

// The checks the library would make on MeasuredPoints, made first with the names the Python
// caller used (`robot`, `weights`), so that the message names the argument, not a C++ member.
void check_count(const char* what, Eigen::Index count, Eigen::Index n) {
  if (count != n) {
    throw InputError(fmt::format("{}: expected {} entries, one per row of sensor, got {}", what,
                                 n, count));
  }
}

template <typename Matrix>
void check_finite(const char* what, const Matrix& values) {
  for (Eigen::Index c = 0; c < values.cols(); ++c) {
    for (Eigen::Index r = 0; r < values.rows(); ++r) {
      if (!std::isfinite(values(r, c))) {
        throw InputError(fmt::format("{}: values not all finite (row {} holds {})", what, c,
                                     values(r, c)));
      }
    }
  }
}

void check_like_python(const MeasuredPoints& p, const PointExtras& extras) {
  const Eigen::Index n = p.size();
  check_finite("sensor", p.sensor_m);
  if (p.robot_m.cols() > 0) {
    check_count("robot", p.robot_m.cols(), n);
    check_finite("robot", p.robot_m);
  }
  if (!extras.weights.is_none()) {
    check_count("weights", p.weights.size(), n);
    check_finite("weights", p.weights.transpose());
  }
  if (!extras.names.is_none()) check_count("names", static_cast<Eigen::Index>(p.names.size()), n);
  if (!extras.configs.is_none()) {
    check_count("configs", static_cast<Eigen::Index>(p.configs.size()), n);
  }
  if (!extras.joints.is_none()) {
    check_count("joints", p.joints_rad.cols(), n);
    check_finite("joints", p.joints_rad);
  }
  if (!extras.n_readings.is_none()) check_count("n_readings", p.n_readings.size(), n);
  if (!extras.sensor_sq_dev.is_none()) {
    check_count("sensor_sq_dev", p.sensor_sq_dev_m2.cols(), n);
    check_finite("sensor_sq_dev", p.sensor_sq_dev_m2);
  }
  if (!extras.sensor_q.is_none()) {
    check_count("sensor_q", static_cast<Eigen::Index>(p.q_sensor_marker.size()), n);
  }
  if (!extras.robot_q.is_none()) {
    check_count("robot_q", static_cast<Eigen::Index>(p.q_robot_marker.size()), n);
  }
}

// An (N, 4) array of unit quaternions (x, y, z, w), each checked as the library checks them
// but named as the Python caller named the argument and row.
std::vector<Eigen::Quaterniond> quaternions_from(const py::handle& array, const char* what) {
  const Eigen::MatrixXd xyzw = rows_from(array, what, -1, 4);
  std::vector<Eigen::Quaterniond> out;
  out.reserve(static_cast<std::size_t>(xyzw.cols()));
  for (Eigen::Index i = 0; i < xyzw.cols(); ++i) {
    const std::string row = fmt::format("{} row {}", what, i);
    out.push_back(unit_quaternion(xyzw.col(i), row.c_str()));
  }
  return out;
}

// The approach signs (n_joints x N) from approach_from_q or approach_sign, checked against the
// joints and named as the caller named them; 0 x 0 when neither is given.
Eigen::MatrixXd approach_signs_of(const MeasuredPoints& p, const PointExtras& extras) {
  const bool from = !extras.approach_from_q.is_none();
  const bool signs = !extras.approach_sign.is_none();
  if (!from && !signs) return {};
  if (from && signs) throw InputError("approach_from_q, approach_sign: give one of them, not both");
  const char* what = from ? "approach_from_q" : "approach_sign";
  const Eigen::MatrixXd values =
      rows_from(from ? extras.approach_from_q : extras.approach_sign, what, -1, -1);
  check_count(what, values.cols(), p.size());
  check_finite(what, values);
  if (from && p.joints_rad.cols() == 0) {
    throw InputError("approach_from_q: needs joints (the approach sign is that of joints - from)");
  }
  if (p.joints_rad.cols() > 0 && values.rows() != p.joints_rad.rows()) {
    throw InputError(fmt::format("{}: {} joints per row, joints has {}", what, values.rows(),
                                 p.joints_rad.rows()));
  }
  if (!from) {
    for (Eigen::Index i = 0; i < values.cols(); ++i) {
      for (Eigen::Index j = 0; j < values.rows(); ++j) {
        const double v = values(j, i);
        if (v != -1.0 && v != 0.0 && v != 1.0) {
          throw InputError(
              fmt::format("approach_sign: row {} holds {}; a sign is -1, 0 or 1", i, v));
        }
      }
    }
    return values + Eigen::MatrixXd::Zero(values.rows(), values.cols());  // no -0
  }
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(values.rows(), values.cols());
  for (Eigen::Index i = 0; i < values.cols(); ++i) {
    Eigen::VectorXd sign = Eigen::VectorXd::Zero(values.rows());
    update_approach_sign(values.col(i), p.joints_rad.col(i), sign);
    out.col(i) = sign;
  }
  return out;
}

}  // namespace

MeasuredPoints measured_points(const py::handle& sensor, const py::handle& robot,
                               const PointExtras& extras) {
  MeasuredPoints p;
  p.sensor_m = points_from(sensor, "sensor");
  if (!robot.is_none()) p.robot_m = points_from(robot, "robot");
  if (!extras.weights.is_none()) p.weights = vector_from(extras.weights, "weights");
  if (!extras.names.is_none()) {
    if (py::isinstance<py::str>(extras.names) || !py::isinstance<py::sequence>(extras.names)) {
      throw InputError("names: expected a sequence of str, one per row of sensor");
    }
    p.names = extras.names.cast<std::vector<std::string>>();
  }
  if (!extras.configs.is_none()) p.configs = ints_from(extras.configs, "configs", -1);
  if (!extras.joints.is_none()) p.joints_rad = rows_from(extras.joints, "joints", -1);
  if (!extras.n_readings.is_none()) {
    const std::vector<int> n = ints_from(extras.n_readings, "n_readings", -1);
    p.n_readings = Eigen::Map<const Eigen::VectorXi>(n.data(), static_cast<Eigen::Index>(n.size()));
  }
  if (!extras.sensor_sq_dev.is_none()) {
    p.sensor_sq_dev_m2 = points_from(extras.sensor_sq_dev, "sensor_sq_dev");
  }
  if (!extras.sensor_q.is_none()) p.q_sensor_marker = quaternions_from(extras.sensor_q, "sensor_q");
  if (!extras.robot_q.is_none()) p.q_robot_marker = quaternions_from(extras.robot_q, "robot_q");
  check_like_python(p, extras);
  p.approach_sign = approach_signs_of(p, extras);
  return p;
}

const MeasurementSet* as_measurements(const py::handle& data) {
  if (!py::isinstance<MeasurementSet>(data)) return nullptr;
  return &data.cast<const MeasurementSet&>();
}

}  // namespace vrreg::python
