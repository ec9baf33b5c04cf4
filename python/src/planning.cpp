// SPDX-License-Identifier: Apache-2.0
// Procedure 1 (paper section 6): where to measure around part points, with joints for every
// location; on the simulated test beds' robots ('ur5', 'lwr4') their tool, orientation, arm angle
// and home joints are taken, as `vrreg plan --robot ur5|lwr4` does.
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/configuration_order.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::python {
namespace {

// sigma_noise of the paper's KUKA LWR 4+ test bed (section 5.2) [m], as `vrreg plan` uses.
constexpr double kPaperKukaSigmaNoiseM = 0.077e-3;

struct PlanSetup {
  kinematics::SerialChain chain;
  planning::PlanOptions options;
};

PlanSetup testbed_setup(const std::string& robot) {
  VRREG_THROW_UNLESS(
      robot == "ur5" || robot == "lwr4",
      "plan: robot must be a simulated test bed's, 'ur5' or 'lwr4'; got '" << robot << "'");
  const simulation::Testbed testbed = simulation::testbed_by_name(robot);
  PlanSetup s{kinematics::robot_by_name(robot)->with_tool(testbed.nominal.T_flange_tcp()), {}};
  s.options.arm.R_base_tcp = testbed.tcp_rotation;
  s.options.arm.home_q_rad = testbed.home_q_rad;
  if (testbed.kind == simulation::TestbedKind::kLwr4) {
    s.options.arm.psi_rad = testbed.arm_angle_rad;
    s.options.sigma_noise_m = kPaperKukaSigmaNoiseM;
  }
  return s;
}

std::vector<std::string> location_names(const planning::PlanResult& p) {
  std::vector<std::string> out;
  for (const auto& l : p.locations) out.push_back(l.point);
  return out;
}

}  // namespace

void bind_planning(py::module_& m) {
  py::class_<planning::PlanResult>(
      m, "Plan", "A Procedure 1 plan: locations in visiting order; metres, radians.")
      .def_property_readonly("ok", &planning::PlanResult::ok)
      .def_property_readonly("message", [](const planning::PlanResult& p) { return p.message; })
      .def_property_readonly("names", &location_names)
      .def_property_readonly(
          "roles",
          [](const planning::PlanResult& p) {
            std::vector<std::string> out;
            for (const auto& l : p.locations)
              out.emplace_back(l.role == Role::kFiducial ? "fiducial" : "target");
            return out;
          })
      .def_property_readonly(
          "robot",
          [](const planning::PlanResult& p) {
            Points3 out(3, static_cast<Eigen::Index>(p.locations.size()));
            for (std::size_t i = 0; i < p.locations.size(); ++i)
              out.col(static_cast<Eigen::Index>(i)) = p.locations[i].robot_m;
            return to_numpy(std::move(out));
          },
          "(N, 3) TCP positions to visit, robot base frame [m]")
      .def_property_readonly(
          "joints",
          [](const planning::PlanResult& p) {
            const Eigen::Index n_joints =
                p.locations.empty() ? 0 : p.locations.front().q_rad.size();
            Eigen::MatrixXd q(n_joints, static_cast<Eigen::Index>(p.locations.size()));
            for (std::size_t i = 0; i < p.locations.size(); ++i)
              q.col(static_cast<Eigen::Index>(i)) = p.locations[i].q_rad;
            return columns_as_rows(q);
          },
          "(N, n_joints) commanded joints [rad]")
      .def_property_readonly(
          "configs",
          [](const planning::PlanResult& p) {
            std::vector<int> out;
            for (const auto& l : p.locations) out.push_back(l.config.index());
            return out;
          },
          "configuration label index per location")
      .def_property_readonly(
          "d_min", [](const planning::PlanResult& p) { return p.cube.d_min_m(); },
          "target-fiducial distance d_min [m] (Eq. 9 wants > 2.5 sigma_noise)")
      .def("__len__", [](const planning::PlanResult& p) { return p.locations.size(); })
      .def("__repr__", [](const planning::PlanResult& p) {
        return "<vrreg.Plan " + std::string(planning::to_string(p.status)) + ": " +
               std::to_string(p.parts.size()) + " parts, " + std::to_string(p.locations.size()) +
               " locations>";
      });

  m.def(
      "plan",
      [](const py::object& parts, const std::vector<std::string>& names, const std::string& robot,
         double halfwidth, double spacing, std::optional<double> sigma_noise, bool force,
         const std::string& joint_norm) {
        const Points3 positions = points_from(parts, "parts");
        VRREG_THROW_UNLESS(
            static_cast<Eigen::Index>(names.size()) == positions.cols(),
            "plan: " << names.size() << " names for " << positions.cols() << " part points");
        PlanSetup s = testbed_setup(robot);
        s.options.halfwidth_m = halfwidth;
        s.options.spacing_m = spacing;
        if (sigma_noise) s.options.sigma_noise_m = *sigma_noise;
        s.options.force = force;
        s.options.arm.norm = kinematics::parse_joint_norm(joint_norm);
        std::vector<planning::PartPoint> points;
        for (Eigen::Index i = 0; i < positions.cols(); ++i) {
          points.push_back({names[static_cast<std::size_t>(i)], positions.col(i)});
        }
        py::gil_scoped_release nogil;
        return planning::make_plan(s.chain, points, s.options);
      },
      py::arg("parts"), py::arg("names"), py::kw_only(), py::arg("robot") = "ur5",
      py::arg("halfwidth"), py::arg("spacing"), py::arg("sigma_noise") = py::none(),
      py::arg("force") = false, py::arg("joint_norm") = "l2",
      "Procedure 1 (section 6): a cube of fiducials of edge 2 * halfwidth [m] on a grid of "
      "`spacing` [m] around each part point ((M, 3) in METRES, robot base frame, with M names), "
      "the d_min > 2.5 sigma_noise check (Eq. 9; force=True plans anyway), joints for every "
      "location on the test bed robot 'ur5' or 'lwr4' and a visiting order. Measure it with "
      "simulate(robot, plan=...).");
}

}  // namespace vrreg::python
