// SPDX-License-Identifier: Apache-2.0
#pragma once
// The front door's inputs from Python: arrays (with optional per-point extras) into
// vrreg::MeasuredPoints, or a vrreg.Measurements object used as it is.
#include <pybind11/pybind11.h>

#include "vrreg/pipeline/points.hpp"

namespace vrreg::python {

namespace py = pybind11;

/// Per-point extras of register / evaluate / correct (None: not given).
struct PointExtras {
  py::object weights = py::none();        ///< (N,) registration weights (Eq. 2)
  py::object names = py::none();          ///< N labels
  py::object configs = py::none();        ///< (N,) integer configuration labels
  py::object joints = py::none();         ///< (N, n_joints) [rad]
  py::object n_readings = py::none();     ///< (N,) repeat readings per location
  py::object sensor_sq_dev = py::none();  ///< (N, 3) per-axis sums of squared deviations [m^2]
  py::object sensor_q = py::none();  ///< (N, 4) measured orientations, sensor frame (x, y, z, w)
  py::object robot_q = py::none();   ///< (N, 4) commanded orientations, robot frame (x, y, z, w)
  /// (N, n_joints) joints the robot comes from [rad]: the approach sign is that of joints - from
  py::object approach_from_q = py::none();
  py::object approach_sign = py::none();  ///< (N, n_joints) approach signs, each -1, 0 or 1
};

/// sensor (N, 3) [m], robot (N, 3) [m] or None, and the extras, copied once into the library's
/// input; counts and finiteness are checked by the library (InputError -> ValueError).
MeasuredPoints measured_points(const py::handle& sensor, const py::handle& robot,
                               const PointExtras& extras);

/// The Measurements object `data` is, or nullptr when it is something else (an array).
const MeasurementSet* as_measurements(const py::handle& data);

}  // namespace vrreg::python
