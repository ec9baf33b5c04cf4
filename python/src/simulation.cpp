// SPDX-License-Identifier: Apache-2.0
// The simulated test beds (paper section 4): one of the paper's datasets ('ur5': A1, A2, B;
// 'lwr4': grid) or a Procedure 1 plan, measured with a seed. The result holds the readings as
// arrays and, averaged per visit, a vrreg.Measurements for register / evaluate.
#include <pybind11/stl.h>

#include <cmath>

#include "arrays.hpp"
#include "bindings.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"

namespace vrreg::python {
namespace {

struct Simulation {
  simulation::SimulatedDataset data;
  MeasurementSet measurements;
};

std::vector<simulation::CommandedLocation> commanded(const planning::PlanResult& plan) {
  VRREG_THROW_UNLESS(plan.ok(), "simulate: the plan is not usable: " << plan.message);
  std::vector<simulation::CommandedLocation> out;
  for (const planning::PlannedLocation& l : plan.locations) {
    out.push_back({l.point, l.role, l.robot_m, l.config.index(), l.q_rad});
  }
  return out;
}

Points3 readings_sensor(const Simulation& s) {
  Points3 out(3, static_cast<Eigen::Index>(s.data.readings.size()));
  for (std::size_t i = 0; i < s.data.readings.size(); ++i) {
    out.col(static_cast<Eigen::Index>(i)) = s.data.readings[i].sensor_m;
  }
  return out;
}

Points3 visits_tcp(const Simulation& s) {
  Points3 out(3, static_cast<Eigen::Index>(s.data.visits.size()));
  for (std::size_t i = 0; i < s.data.visits.size(); ++i) {
    out.col(static_cast<Eigen::Index>(i)) = s.data.visits[i].tcp_m;
  }
  return out;
}

std::vector<int> reading_visits(const Simulation& s) {
  std::vector<int> out;
  for (const auto& r : s.data.readings) out.push_back(r.visit);
  return out;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<Simulation>(m, "Simulation",
                         "A simulated dataset: readings, visits and the truth; metres, radians.")
      .def_property_readonly(
          "measurements",
          [](const Simulation& s) -> const MeasurementSet& { return s.measurements; },
          py::return_value_policy::reference_internal,
          "one location per visit, readings averaged (vrreg.Measurements)")
      .def_property_readonly("testbed", [](const Simulation& s) { return s.data.testbed; })
      .def_property_readonly(
          "dataset",
          [](const Simulation& s) { return std::string(simulation::to_string(s.data.dataset)); })
      .def_property_readonly("seed", [](const Simulation& s) { return s.data.seed; })
      .def_property_readonly(
          "sigma_rep_spec", [](const Simulation& s) { return s.data.sigma_rep_spec_m; },
          "the robot's specified repeatability, for sigma_noise (Eq. 9) [m]")
      .def_property_readonly(
          "true_rotation",
          [](const Simulation& s) { return matrix_copy(s.data.T_robot_sensor.rotation); },
          "the true tracker rotation R of T_robot_sensor (3, 3)")
      .def_property_readonly(
          "true_translation",
          [](const Simulation& s) { return vector_copy(s.data.T_robot_sensor.translation_m); },
          "the true tracker translation tau, robot frame [m]")
      .def_property_readonly(
          "readings_sensor", [](const Simulation& s) { return to_numpy(readings_sensor(s)); },
          "(R, 3) every tracker reading, sensor frame [m]")
      .def_property_readonly("reading_visit", &reading_visits, "visit index of each reading")
      .def_property_readonly(
          "visit_tcp", [](const Simulation& s) { return to_numpy(visits_tcp(s)); },
          "(V, 3) true TCP position of each visit, robot frame [m]")
      .def("__repr__", [](const Simulation& s) {
        return "<vrreg.Simulation " + s.data.testbed + " " + simulation::to_string(s.data.dataset) +
               ", seed " + std::to_string(s.data.seed) + ": " +
               std::to_string(s.data.locations.size()) + " locations, " +
               std::to_string(s.data.visits.size()) + " visits, " +
               std::to_string(s.data.readings.size()) + " readings>";
      });

  m.def(
      "simulate",
      [](const std::string& testbed_name, std::optional<std::string> dataset,
         const planning::PlanResult* plan, std::uint64_t seed, double rigid_body_mm) {
        VRREG_THROW_UNLESS(dataset.has_value() != (plan != nullptr),
                           "simulate: give a dataset (ur5: A1, A2 or B; lwr4: grid) or plan=, "
                           "not both");
        const simulation::Testbed testbed = simulation::testbed_by_name(testbed_name);
        simulation::SimulationOptions options;
        options.seed = seed;
        VRREG_THROW_UNLESS(std::isfinite(rigid_body_mm) && rigid_body_mm >= 0.0,
                           "simulate: rigid_body_mm must be finite and >= 0");
        if (rigid_body_mm > 0.0) {
          options.errors = testbed.default_errors;
          options.errors->tracker.rigid_body_radius_m = rigid_body_mm / 1000.0;
        }
        std::vector<simulation::CommandedLocation> locations;
        if (plan) locations = commanded(*plan);
        std::optional<simulation::Dataset> which;
        if (dataset) {
          which = simulation::parse_dataset(*dataset);
          simulation::check_dataset(testbed.kind, *which);
        }
        py::gil_scoped_release nogil;
        Simulation s;
        s.data = which ? simulation::simulate_dataset(testbed, *which, options)
                       : simulation::simulate_plan(testbed, locations, options);
        s.measurements = experiments::to_measurement_set(s.data);
        s.measurements.source = testbed.name + " " + simulation::to_string(s.data.dataset) +
                                " seed " + std::to_string(seed);
        return s;
      },
      py::arg("testbed"), py::arg("dataset") = py::none(), py::kw_only(),
      py::arg("plan") = py::none(), py::arg("seed") = 1, py::arg("rigid_body_mm") = 0.0,
      "Simulates one of the paper's datasets on a test bed ('ur5': 'A1', 'A2', 'B'; 'lwr4': "
      "'grid'), or measures a Procedure 1 plan (plan=vrreg.plan(...)), with `seed` (same seed, "
      "same numbers, as `vrreg simulate`). Positions in METRES. rigid_body_mm > 0: a rigid body "
      "of 4 spheres on that radius, so the measurements carry orientations "
      "(docs/orientation.md); positions stay as without it.");
}

}  // namespace vrreg::python
