// SPDX-License-Identifier: Apache-2.0
// For python/benchmarks/bench.py: the same register / correct calls timed inside C++ on input
// already converted, so that the difference to the Python call is the binding's overhead.
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <limits>

#include "bindings.hpp"
#include "points.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::python {
namespace {

// The fastest of `repeats` runs of `run` [s], without the GIL.
template <typename Run>
double best_seconds(int repeats, Run&& run) {
  py::gil_scoped_release nogil;
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < std::max(repeats, 1); ++k) {
    const auto start = std::chrono::steady_clock::now();
    run();
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace

void bind_timing(py::module_& m) {
  m.def(
      "_cpp_seconds_register",
      [](const py::object& sensor, const py::object& robot, int repeats, bool rigid_body) {
        const MeasuredPoints points = measured_points(sensor, robot, {});
        RegisterOptions options;
        options.rigid_body_statistics = rigid_body;
        return best_seconds(repeats, [&] { (void)register_fiducials(points, options); });
      },
      py::arg("sensor"), py::arg("robot"), py::arg("repeats"), py::arg("rigid_body"));
  m.def(
      "_cpp_seconds_correct",
      [](const RegistrationModel& model, const py::object& sensor, int repeats) {
        const MeasuredPoints points = measured_points(sensor, py::none(), {});
        return best_seconds(repeats, [&] { (void)correct(model, points, {}); });
      },
      py::arg("model"), py::arg("sensor"), py::arg("repeats"));
}

}  // namespace vrreg::python
