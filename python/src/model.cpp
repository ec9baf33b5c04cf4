// SPDX-License-Identifier: Apache-2.0
// vrreg.Model: the registration model (what register builds, the model file holds, evaluate and
// correct use), saved and loaded as the command line's JSON file (include/vrreg/io/model_json.hpp).
#include "vrreg/pipeline/model.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "paths.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/model_json.hpp"

namespace vrreg::python {
namespace {

Points3 fiducial_column(const RegistrationModel& model, bool robot) {
  Points3 out(3, static_cast<Eigen::Index>(model.fiducials.size()));
  for (std::size_t j = 0; j < model.fiducials.size(); ++j) {
    out.col(static_cast<Eigen::Index>(j)) =
        robot ? model.fiducials[j].robot_m : model.fiducials[j].sensor_m;
  }
  return out;
}

std::string model_repr(const RegistrationModel& model) {
  return fmt::format("<vrreg.Model {} fiducials, FRE {:.4f} mm, interpolation {}, source '{}'>",
                     model.fiducials.size(), units::m_to_mm(model.fre_m),
                     to_string(model.interpolation.method), model.source);
}

// T_robot_sensor as a 4 x 4 homogeneous matrix, [s R, tau; 0 0 0 1] (tau in metres).
Eigen::Matrix4d homogeneous(const SimilarityTransform& T) {
  Eigen::Matrix4d out = Eigen::Matrix4d::Identity();
  out.topLeftCorner<3, 3>() = T.scale * T.rotation;
  out.topRightCorner<3, 1>() = T.translation_m;
  return out;
}

// Y = s R X + tau on (N, 3) positions, or on one (3,) position (then a (3,) result, as scipy's
// Rotation.apply and Open3D's transform do).
py::array apply_to(const RegistrationModel& model, const py::handle& points) {
  const py::array a = py::array::ensure(points);
  const bool single = a && a.ndim() == 1;
  Points3 mapped = model.T_robot_sensor.apply_all(points_from(points, "points"));
  if (single) return vector_copy(mapped.col(0));
  return to_numpy(std::move(mapped));
}

}  // namespace

void bind_model(py::module_& m) {
  py::class_<RegistrationModel>(
      m, "Model",
      "A registration model: {R, tau} (Eq. 2), the fiducials and their RRBC corrections (Eq. 6), "
      "the default interpolation (Eq. 7) and the Procedure 2 strategy. Lengths in metres.")
      .def_property_readonly(
          "rotation",
          [](const RegistrationModel& s) { return matrix_copy(s.T_robot_sensor.rotation); },
          "R (3, 3): sensor -> robot rotation, Y ~ s R X + tau (Eq. 2)")
      .def_property_readonly(
          "translation",
          [](const RegistrationModel& s) { return vector_copy(s.T_robot_sensor.translation_m); },
          "tau (3,): sensor -> robot translation, robot frame [m]")
      .def_property_readonly(
          "scale", [](const RegistrationModel& s) { return s.T_robot_sensor.scale; },
          "uniform scale s (1 unless register(scale=True))")
      .def_property_readonly(
          "fre", [](const RegistrationModel& s) { return s.fre_m; },
          "FRE of the registration (Eq. 2) [m]")
      .def_property_readonly(
          "sigma_l", [](const RegistrationModel& s) { return s.sigma_l_m; },
          "sigma_L over the registered fiducial pairs (Eq. 1) [m]")
      .def_property_readonly(
          "sigma_rep", [](const RegistrationModel& s) { return optional_value(s.sigma_rep_m); },
          "robot repeatability given to register (Eq. 9) [m], or None")
      .def_property_readonly(
          "config", [](const RegistrationModel& s) { return optional_value(s.config); },
          "configuration label the model was built for, or None")
      .def_property_readonly(
          "interpolation",
          [](const RegistrationModel& s) { return std::string(to_string(s.interpolation.method)); },
          "default interpolation of evaluate and correct (Eq. 7)")
      .def_property_readonly(
          "cube_edge", [](const RegistrationModel& s) { return s.interpolation.cube_edge_m; },
          "octuplet cube edge [m] (0: not set)")
      .def_property_readonly(
          "strategy",
          [](const RegistrationModel& s) {
            return planning::strategy_number(s.procedure2.strategy);
          },
          "Procedure 2 strategy 1-3 (section 4.4), 0 for none")
      .def_property_readonly(
          "source", [](const RegistrationModel& s) { return s.source; },
          "the fiducial file (or 'arrays') the model came from")
      .def_property_readonly("n_fiducials",
                             [](const RegistrationModel& s) { return s.fiducials.size(); })
      .def_property_readonly("fiducial_names",
                             [](const RegistrationModel& s) {
                               std::vector<std::string> names;
                               for (const Location& l : s.fiducials) names.push_back(l.point);
                               return names;
                             })
      .def_property_readonly(
          "fiducials_robot",
          [](const RegistrationModel& s) { return to_numpy(fiducial_column(s, true)); },
          "(N, 3) nominal fiducial positions, robot frame [m]")
      .def_property_readonly(
          "fiducials_sensor",
          [](const RegistrationModel& s) { return to_numpy(fiducial_column(s, false)); },
          "(N, 3) averaged measured fiducial positions, sensor frame [m]")
      .def_property_readonly(
          "corrections",
          [](py::object self) {
            return view_of(self.cast<const RegistrationModel&>().corrections_sensor_m, self);
          },
          "(N, 3) RRBC corrections epsilon_j (Eq. 6), sensor frame [m]")
      .def(
          "save",
          [](const RegistrationModel& s, const PathText& path) {
            io::write_model_json(path.text, s);
          },
          py::arg("path"),
          "Writes the model file of `vrreg register -o` (JSON, whole or not at all).")
      .def(
          "to_json", [](const RegistrationModel& s) { return io::format_model_json(s); },
          "The model file's text (JSON).")
      .def(
          "as_matrix",
          [](const RegistrationModel& s) { return matrix_copy(homogeneous(s.T_robot_sensor)); },
          "T_robot_sensor as a (4, 4) homogeneous matrix [s R, tau; 0, 1] (tau in metres), as "
          "scipy's Rotation.as_matrix and Open3D's transform take it.")
      .def("apply", &apply_to, py::arg("points"),
           "s R X + tau (Eq. 2) of (N, 3) sensor-frame positions [m], or of one (3,) position: "
           "the registration alone. vrreg.correct(model, points) adds the RRBC correction.")
      .def("__repr__", &model_repr)
      // pickle, copy.copy and copy.deepcopy go through the model file's JSON, the one complete
      // serialisation of a model (what `vrreg register -o` writes and load_model reads).
      .def(py::pickle(
          [](const RegistrationModel& s) { return py::make_tuple(io::format_model_json(s)); },
          [](const py::tuple& state) {
            if (state.size() != 1) throw InputError("Model: bad pickle state");
            return io::parse_model_json(state[0].cast<std::string>(), "<pickle>");
          }))
      // Protocols 0 and 1 would bypass __getstate__ (copyreg's _reduce_ex, which aborts on a
      // pybind11 type): every protocol gets protocol 2's recipe, a bare Model that
      // __setstate__ fills from the JSON.
      .def(
          "__reduce_ex__",
          [](const py::object& self, int /*protocol*/) {
            return py::make_tuple(py::module_::import("copyreg").attr("__newobj__"),
                                  py::make_tuple(py::type::of(self)), self.attr("__getstate__")());
          },
          py::arg("protocol"))
      .def("__copy__", [](const RegistrationModel& s) { return RegistrationModel(s); })
      .def(
          "__deepcopy__",
          [](const RegistrationModel& s, const py::dict&) { return RegistrationModel(s); },
          py::arg("memo"));

  m.def(
      "load_model", [](const PathText& path) { return io::read_model_json(path.text); },
      py::arg("path"),
      "Reads a model file written by Model.save or `vrreg register -o`; FileError (a ValueError) "
      "on a missing, truncated or invalid file.");
  m.def(
      "model_from_json",
      [](const std::string& text) { return io::parse_model_json(text, "<string>"); },
      py::arg("text"), "Parses model JSON text (Model.to_json's).");
}

}  // namespace vrreg::python
