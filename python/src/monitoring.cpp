// SPDX-License-Identifier: Apache-2.0
// check / update: does a registration still hold (the model's monitor points read again), and a
// new model version from a few points after a bump or a drift (pipeline/check.hpp, update.hpp).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "points.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/io/monitor_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::python {
namespace {

const MeasurementSet& measurements_of(const py::handle& data, const char* what) {
  const MeasurementSet* set = as_measurements(data);
  VRREG_THROW_UNLESS(set != nullptr, what << " must be a vrreg.Measurements (read_measurements): "
                                             "monitor rows and their visits come from a file");
  return *set;
}

py::array_t<double> vector_of(const Eigen::Vector3d& v) {
  py::array_t<double> out(3);
  for (py::ssize_t i = 0; i < 3; ++i) out.mutable_at(i) = v(i);
  return out;
}

}  // namespace

void bind_monitoring(py::module_& m) {
  py::class_<CheckResult>(m, "CheckResult",
                          "Whether a registration still holds; lengths in metres.")
      .def_property_readonly(
          "verdict",
          [](const CheckResult& r) { return std::string(to_string(r.statistics.verdict)); },
          "'valid', 'rigid change' (the sensor moved), 'smooth change' (the robot drifted), "
          "'outlier' (one monitor point moved) or 'noisier today' (nothing found, the readings "
          "scatter more than at registration)")
      .def_property_readonly("message", [](const CheckResult& r) { return r.statistics.message; })
      .def_property_readonly(
          "change_rms", [](const CheckResult& r) { return r.statistics.change_rms_m; },
          "RMS difference at the monitor points [m]")
      .def_property_readonly(
          "visit_sd", [](const CheckResult& r) { return r.visit_sd_m; },
          "sd of one visit's mean reading per axis [m]")
      .def_property_readonly(
          "visit_sd_dof", [](const CheckResult& r) { return r.variance_dof; },
          "its degrees of freedom when estimated from the visits (0: given)")
      .def_property_readonly(
          "sensor_rotation",
          [](const CheckResult& r) -> py::object {
            if (!r.statistics.rigid) return py::none();
            return vector_of(r.statistics.rigid->rotation_rad);
          },
          "rigid change: the sensor's small rotation omega [rad] (sensor frame), else None")
      .def_property_readonly(
          "sensor_translation",
          [](const CheckResult& r) -> py::object {
            if (!r.statistics.rigid) return py::none();
            return vector_of(r.statistics.rigid->translation_m);
          },
          "rigid change: the sensor's translation [m], else None")
      .def_property_readonly(
          "outlier",
          [](const CheckResult& r) -> py::object {
            if (!r.statistics.outlier) return py::none();
            return py::str(r.points[static_cast<std::size_t>(*r.statistics.outlier)].point);
          },
          "outlier: the monitor point that moved, else None")
      .def_property_readonly(
          "remeasure", [](const CheckResult& r) { return r.remeasure; },
          "smooth change: the fiducials to read again for update(change='drift')")
      .def(
          "to_json", [](const CheckResult& r) { return with_keywords(io::check_json(r).dump(2)); },
          "the JSON `vrreg check --json` prints (lengths in mm), as a string")
      .def("__repr__", [](const CheckResult& r) {
        return "CheckResult(" + std::string(to_string(r.statistics.verdict)) + ": " +
               r.statistics.message + ")";
      });

  py::class_<UpdateResult>(m, "UpdateResult", "A model updated from a few points; metres.")
      .def_property_readonly(
          "model", [](const UpdateResult& r) { return r.model; },
          "the new model (its lineage names the old one, the points and time)")
      .def_property_readonly("points", [](const UpdateResult& r) { return r.points; })
      .def_property_readonly(
          "fit_rms", [](const UpdateResult& r) { return r.fit_rms_m; },
          "RMS residual of the update's fit [m]")
      .def(
          "to_json",
          [](const UpdateResult& r) { return with_keywords(io::update_json(r).dump(2)); },
          "the JSON `vrreg update --json` prints (lengths in mm), as a string")
      .def("__repr__", [](const UpdateResult& r) {
        return "UpdateResult(" + r.model.lineage.back().change + " from " +
               std::to_string(r.points.size()) + " points)";
      });

  m.def(
      "check",
      [](const RegistrationModel& model, const py::object& monitors, double false_alarm_rate,
         std::optional<double> visit_sd, int remeasure) {
        CheckOptions options;
        options.false_alarm_rate = false_alarm_rate;
        options.visit_sd_m = visit_sd;
        options.remeasure = remeasure;
        const MeasurementSet& today = measurements_of(monitors, "monitors");
        py::gil_scoped_release nogil;
        return check_cell(model, today, options);
      },
      py::arg("model"), py::arg("monitors"), py::kw_only(), py::arg("false_alarm_rate") = 0.01,
      py::arg("visit_sd") = py::none(), py::arg("remeasure") = 10,
      "Compares today's readings of the model's monitor points with theirs at registration: "
      "valid, the sensor moved, one point moved, or the robot drifted. Metres.");
  m.def(
      "update",
      [](const RegistrationModel& model, const py::object& points, const std::string& change,
         const std::string& parent, const std::string& time, bool even_if_unchanged) {
        VRREG_THROW_UNLESS(change == "bump" || change == "drift",
                           "`change` must be 'bump' or 'drift', got '" << change << "'");
        UpdateOptions options;
        options.change = change == "bump" ? CellChange::kBump : CellChange::kDrift;
        options.parent = parent;
        options.time = time.empty() ? io::utc_now() : time;
        options.even_if_unchanged = even_if_unchanged;
        const MeasurementSet& today = measurements_of(points, "points");
        py::gil_scoped_release nogil;
        return update_model(model, today, options);
      },
      py::arg("model"), py::arg("points"), py::kw_only(), py::arg("change"), py::arg("parent") = "",
      py::arg("time") = "", py::arg("even_if_unchanged") = false,
      "A new model version from monitor and fiducial rows read today: after a bump the sensor's "
      "move (the field kept), after a drift an affine change and a refit. Refused when today's "
      "monitor rows, checked again, show no change, unless even_if_unchanged.");
}

}  // namespace vrreg::python
