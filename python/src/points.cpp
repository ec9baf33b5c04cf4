// SPDX-License-Identifier: Apache-2.0
#include "points.hpp"

#include <pybind11/stl.h>

#include "arrays.hpp"

namespace vrreg::python {

MeasuredPoints measured_points(const py::handle& sensor, const py::handle& robot,
                               const PointExtras& extras) {
  MeasuredPoints p;
  p.sensor_m = points_from(sensor, "sensor");
  if (!robot.is_none()) p.robot_m = points_from(robot, "robot");
  if (!extras.weights.is_none()) p.weights = vector_from(extras.weights, "weights");
  if (!extras.names.is_none()) p.names = extras.names.cast<std::vector<std::string>>();
  if (!extras.configs.is_none()) p.configs = ints_from(extras.configs, "configs", -1);
  if (!extras.joints.is_none()) p.joints_rad = rows_from(extras.joints, "joints", -1);
  if (!extras.n_readings.is_none()) {
    const std::vector<int> n = ints_from(extras.n_readings, "n_readings", -1);
    p.n_readings = Eigen::Map<const Eigen::VectorXi>(n.data(), static_cast<Eigen::Index>(n.size()));
  }
  if (!extras.sensor_sq_dev.is_none()) {
    p.sensor_sq_dev_m2 = points_from(extras.sensor_sq_dev, "sensor_sq_dev");
  }
  return p;
}

const MeasurementSet* as_measurements(const py::handle& data) {
  if (!py::isinstance<MeasurementSet>(data)) return nullptr;
  return &data.cast<const MeasurementSet&>();
}

}  // namespace vrreg::python
