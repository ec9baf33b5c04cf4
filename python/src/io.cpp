// SPDX-License-Identifier: Apache-2.0
// vrreg.Measurements and read_measurements: a measurement CSV (design.md 6) read by the library's
// own reader (include/vrreg/io/measurement_csv.hpp), so that register / evaluate / correct on it
// give exactly what the command line gives on the same file.
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "paths.hpp"
#include "vrreg/core/measurement.hpp"
#include "vrreg/io/measurement_csv.hpp"

namespace vrreg::python {
namespace {

const char* role_name(Role role) { return role == Role::kFiducial ? "fiducial" : "target"; }

Points3 location_points(const MeasurementSet& set, bool robot) {
  Points3 out(3, static_cast<Eigen::Index>(set.locations.size()));
  for (std::size_t i = 0; i < set.locations.size(); ++i) {
    out.col(static_cast<Eigen::Index>(i)) =
        robot ? set.locations[i].robot_m : set.locations[i].sensor_m;
  }
  return out;
}

// The orientations `member` of every location as (N, 4) x, y, z, w; None unless all have one.
py::object quaternions(const MeasurementSet& set,
                       std::optional<Eigen::Quaterniond> Location::*member) {
  py::array_t<double> out({static_cast<py::ssize_t>(set.locations.size()), py::ssize_t{4}});
  auto q = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < set.locations.size(); ++i) {
    const std::optional<Eigen::Quaterniond>& v = set.locations[i].*member;
    if (!v) return py::none();
    for (int k = 0; k < 4; ++k) q(static_cast<py::ssize_t>(i), k) = v->coeffs()(k);
  }
  return out;
}

py::array joints(const MeasurementSet& set) {
  py::array_t<double> out(
      {static_cast<py::ssize_t>(set.locations.size()), static_cast<py::ssize_t>(set.n_joints)});
  auto q = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < set.locations.size(); ++i) {
    const std::vector<double>& row = set.locations[i].q_rad;
    for (int j = 0; j < set.n_joints; ++j) {
      q(static_cast<py::ssize_t>(i), j) =
          static_cast<std::size_t>(j) < row.size() ? row[static_cast<std::size_t>(j)] : 0.0;
    }
  }
  return out;
}

std::string set_repr(const MeasurementSet& set) {
  const std::size_t fiducials = set.select(Role::kFiducial).size();
  return "<vrreg.Measurements '" + set.source + "': " + std::to_string(set.locations.size()) +
         " locations (" + std::to_string(fiducials) + " fiducials, " +
         std::to_string(set.locations.size() - fiducials) + " targets), " +
         std::to_string(set.n_joints) + " joints" + (set.has_config ? ", config" : "") + ">";
}

}  // namespace

void bind_io(py::module_& m) {
  py::class_<MeasurementSet>(
      m, "Measurements",
      "Locations of a measurement CSV, repeat readings averaged, in file order (the visiting "
      "order). Positions in metres; pass it to register / evaluate / correct as the command line "
      "does.")
      .def("__len__", [](const MeasurementSet& s) { return s.locations.size(); })
      .def_property_readonly("source", [](const MeasurementSet& s) { return s.source; })
      .def_property_readonly(
          "names",
          [](const MeasurementSet& s) {
            std::vector<std::string> out;
            for (const Location& l : s.locations) out.push_back(l.point);
            return out;
          },
          "point label of each location")
      .def_property_readonly(
          "roles",
          [](const MeasurementSet& s) {
            std::vector<std::string> out;
            for (const Location& l : s.locations) out.emplace_back(role_name(l.role));
            return out;
          },
          "'fiducial' or 'target' per location")
      .def_property_readonly(
          "configs",
          [](const MeasurementSet& s) {
            std::vector<std::optional<int>> out;
            for (const Location& l : s.locations) out.push_back(l.config);
            return out;
          },
          "arm configuration label per location (None without a config column)")
      .def_property_readonly(
          "robot", [](const MeasurementSet& s) { return to_numpy(location_points(s, true)); },
          "(N, 3) nominal positions, robot frame [m] (0 where absent)")
      .def_property_readonly(
          "sensor", [](const MeasurementSet& s) { return to_numpy(location_points(s, false)); },
          "(N, 3) mean measured positions, sensor frame [m]")
      .def_property_readonly(
          "n_readings",
          [](const MeasurementSet& s) {
            std::vector<int> out;
            for (const Location& l : s.locations) out.push_back(l.n_readings);
            return out;
          },
          "repeat readings averaged into each location")
      .def_property_readonly("joints", &joints,
                             "(N, n_joints) joint angles [rad] (n_joints may be 0)")
      .def_property_readonly(
          "sensor_q",
          [](const MeasurementSet& s) { return quaternions(s, &Location::q_sensor_marker); },
          "(N, 4) mean measured orientations, sensor frame, unit quaternions (x, y, z, w); None "
          "unless every location has one (rigid-body markers: sensor_qx..qw columns)")
      .def_property_readonly(
          "robot_q",
          [](const MeasurementSet& s) { return quaternions(s, &Location::q_robot_marker); },
          "(N, 4) commanded orientations, robot frame, unit quaternions (x, y, z, w); None "
          "unless every location has one (robot_qx..qw columns)")
      .def_property_readonly("n_joints", [](const MeasurementSet& s) { return s.n_joints; })
      .def_property_readonly("has_config", [](const MeasurementSet& s) { return s.has_config; })
      .def("__repr__", &set_repr);

  m.def(
      "read_measurements",
      [](const PathText& path, bool require_robot) {
        io::CsvReadOptions options;
        options.require_robot = require_robot;
        return io::read_measurement_csv(path.text, options);
      },
      py::arg("path"), py::kw_only(), py::arg("require_robot") = true,
      "Reads a measurement CSV (docs/file-formats.md; mm or m columns, stored in metres) at a str "
      "or os.PathLike path. "
      "require_robot=False accepts sensor-only points (as `vrreg correct --points` reads). "
      "FileError (a ValueError) naming file and line on bad input, or a missing file.");
}

}  // namespace vrreg::python
