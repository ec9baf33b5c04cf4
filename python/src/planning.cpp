// SPDX-License-Identifier: Apache-2.0
// Procedure 1 (paper section 6): where to measure around part points, with joints for every
// location; on the simulated test beds' robots ('ur5', 'lwr4') their tool, orientation, arm angle
// and home joints are taken, as `vrreg plan --robot ur5|lwr4` does.
#include <pybind11/stl.h>

#include <cmath>

#include "arrays.hpp"
#include "bindings.hpp"
#include "points.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/configuration_order.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg/pipeline/plan_next_correction.hpp"
#include "vrreg/planning/plan_next.hpp"
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

template <typename Result>
py::array location_positions(const Result& p) {
  Points3 out(3, static_cast<Eigen::Index>(p.locations.size()));
  for (std::size_t i = 0; i < p.locations.size(); ++i)
    out.col(static_cast<Eigen::Index>(i)) = p.locations[i].robot_m;
  return to_numpy(std::move(out));
}

template <typename Result>
py::array location_joints(const Result& p) {
  const Eigen::Index n_joints = p.locations.empty() ? 0 : p.locations.front().q_rad.size();
  Eigen::MatrixXd q(n_joints, static_cast<Eigen::Index>(p.locations.size()));
  for (std::size_t i = 0; i < p.locations.size(); ++i)
    q.col(static_cast<Eigen::Index>(i)) = p.locations[i].q_rad;
  return columns_as_rows(q);
}

std::vector<planning::PartPoint> part_points(const py::object& parts,
                                             const std::vector<std::string>& names,
                                             const char* what) {
  const Points3 positions = points_from(parts, "parts");
  VRREG_THROW_UNLESS(
      static_cast<Eigen::Index>(names.size()) == positions.cols(),
      what << ": " << names.size() << " names for " << positions.cols() << " part points");
  std::vector<planning::PartPoint> points;
  for (Eigen::Index i = 0; i < positions.cols(); ++i) {
    points.push_back({names[static_cast<std::size_t>(i)], positions.col(i)});
  }
  return points;
}

// NaN (unknown) as None.
py::object metres_or_none(double value) {
  return std::isfinite(value) ? py::object(py::float_(value)) : py::object(py::none());
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

  py::class_<planning::PlanNextResult>(
      m, "PlanNext",
      "The next batch of an adaptive plan (docs/adaptive.md): locations in visiting order and the "
      "kriging correction's predicted sd at the part points; metres, radians.")
      .def_property_readonly("ok", &planning::PlanNextResult::ok)
      .def_property_readonly("message", [](const planning::PlanNextResult& p) { return p.message; })
      .def_property_readonly(
          "decision",
          [](const planning::PlanNextResult& p) { return planning::to_string(p.decision); },
          "'continue' (measure the batch) or 'stop'")
      .def_property_readonly("reason", [](const planning::PlanNextResult& p) { return p.reason; })
      .def_property_readonly("space_filling",
                             [](const planning::PlanNextResult& p) { return p.space_filling; })
      .def_property_readonly("names",
                             [](const planning::PlanNextResult& p) {
                               std::vector<std::string> out;
                               for (const auto& l : p.locations) out.push_back(l.point);
                               return out;
                             })
      .def_property_readonly("robot", &location_positions<planning::PlanNextResult>,
                             "(N, 3) TCP positions to visit, robot base frame [m]")
      .def_property_readonly("joints", &location_joints<planning::PlanNextResult>,
                             "(N, n_joints) commanded joints [rad]")
      .def_property_readonly(
          "configs",
          [](const planning::PlanNextResult& p) {
            std::vector<int> out;
            for (const auto& l : p.locations) out.push_back(l.config.index());
            return out;
          },
          "configuration label index per location")
      .def_property_readonly(
          "part_sd_now",
          [](const planning::PlanNextResult& p) {
            return to_numpy(Eigen::VectorXd(p.part_sd_now_m));
          },
          "(M,) predicted sd of each corrected part point now [m] (empty without a model)")
      .def_property_readonly(
          "part_sd_after",
          [](const planning::PlanNextResult& p) {
            return to_numpy(Eigen::VectorXd(p.part_sd_after_m));
          },
          "(M,) the same with the batch measured [m]")
      .def_property_readonly(
          "predicted_sd_now",
          [](const planning::PlanNextResult& p) { return metres_or_none(p.rms_sd_now_m); },
          "predicted RMS_T at the part points now [m], or None without a model")
      .def_property_readonly(
          "predicted_sd_after",
          [](const planning::PlanNextResult& p) { return metres_or_none(p.rms_sd_after_m); },
          "predicted RMS_T at the part points with the batch measured [m], or None")
      .def_property_readonly(
          "goal_sd", [](const planning::PlanNextResult& p) { return metres_or_none(p.goal_sd_m); },
          "the goal used [m], or None while the noise floor it is a multiple of is unknown")
      .def_property_readonly(
          "noise_floor",
          [](const planning::PlanNextResult& p) { return metres_or_none(p.noise_floor_m); },
          "sqrt(3 (sigma_rep^2 + sigma_opt^2 / K)) [m], or None without repeat readings")
      .def_property_readonly(
          "predicted_by", [](const planning::PlanNextResult& p) { return p.sd_method; },
          "the method whose predicted sd part_sd_now is ('kriging' or plan_next's interpolation)")
      .def_property_readonly(
          "prediction_note", [](const planning::PlanNextResult& p) { return p.sd_note; },
          "why the interpolation asked gave no sd (kriging's was used), or ''")
      .def_property_readonly("n_measured",
                             [](const planning::PlanNextResult& p) { return p.n_measured; })
      .def_property_readonly("n_candidates",
                             [](const planning::PlanNextResult& p) { return p.n_candidates; })
      .def_property_readonly(
          "path", [](const planning::PlanNextResult& p) { return p.path_m; },
          "travel through the batch in visiting order [m]")
      .def("__len__", [](const planning::PlanNextResult& p) { return p.locations.size(); })
      .def("__repr__", [](const planning::PlanNextResult& p) {
        return "<vrreg.PlanNext " + std::string(planning::to_string(p.decision)) + ": " +
               std::to_string(p.n_measured) + " measured, " + std::to_string(p.locations.size()) +
               " planned>";
      });

  m.def(
      "plan_next",
      [](const py::object& parts, const std::vector<std::string>& names, const py::object& measured,
         const py::object& measured_robot, std::optional<double> noise_sd, const std::string& robot,
         std::optional<double> goal_sd, std::optional<double> goal_floor_multiple, double sigma_rep,
         int batch, int budget, double candidate_spacing, double margin,
         const std::string& joint_norm, const std::string& interpolation) {
        const std::vector<planning::PartPoint> points = part_points(parts, names, "plan_next");
        const PlanSetup s = testbed_setup(robot);
        planning::PlanNextOptions o;
        VRREG_THROW_UNLESS(goal_sd.has_value() != goal_floor_multiple.has_value(),
                           "plan_next: give goal_sd or goal_floor_multiple (one of them)");
        if (goal_sd) o.goal_sd_m = *goal_sd;
        o.goal_floor_multiple = goal_floor_multiple;
        o.sigma_rep_m = sigma_rep;
        o.batch_size = batch;
        o.budget = budget;
        o.candidate_spacing_m = candidate_spacing;
        o.margin_m = margin;
        o.arm = s.options.arm;
        o.arm.norm = kinematics::parse_joint_norm(joint_norm);
        planning::MeasuredFiducials fiducials;
        if (const MeasurementSet* set = as_measurements(measured)) {
          VRREG_THROW_UNLESS(measured_robot.is_none(),
                             "plan_next: measured_robot is taken from the Measurements");
          planning::FiducialsWithNoise f = planning::measured_fiducials(*set);
          fiducials = std::move(f.fiducials);
          o.noise_sd_m = f.noise_sd_m;
          const InterpolationMethod method = parse_interpolation_method(interpolation);
          if (method != InterpolationMethod::kKriging) {
            RegisterOptions r;
            r.interpolation.method = method;
            r.robot = s.chain;
            o.correction_sd = correction_sd_at_parts(*set, r);
          }
        } else if (!measured.is_none()) {
          VRREG_THROW_UNLESS(interpolation == "kriging",
                             "plan_next: interpolation other than kriging needs the measured "
                             "fiducials as a vrreg.Measurements (with their joints)");
          VRREG_THROW_UNLESS(!measured_robot.is_none(),
                             "plan_next: measured (sensor positions) needs measured_robot");
          fiducials = {points_from(measured_robot, "measured_robot"),
                       points_from(measured, "measured")};
        } else {
          VRREG_THROW_UNLESS(measured_robot.is_none(),
                             "plan_next: measured_robot without measured");
        }
        if (noise_sd) o.noise_sd_m = *noise_sd;
        py::gil_scoped_release nogil;
        return planning::plan_next(s.chain, points, fiducials, o);
      },
      py::arg("parts"), py::arg("names"), py::arg("measured") = py::none(), py::kw_only(),
      py::arg("measured_robot") = py::none(), py::arg("noise_sd") = py::none(),
      py::arg("robot") = "ur5", py::arg("goal_sd") = py::none(),
      py::arg("goal_floor_multiple") = py::none(), py::arg("sigma_rep") = 0.0, py::arg("batch") = 8,
      py::arg("budget") = 64, py::arg("candidate_spacing") = 0.02, py::arg("margin") = 0.02,
      py::arg("joint_norm") = "l2", py::arg("interpolation") = "kriging",
      "Adaptive planning (docs/adaptive.md), as `vrreg plan-next`: the next batch of fiducial "
      "locations where the kriging correction's predicted sd at the part points ((M, 3) in "
      "METRES, robot base frame, with M names) falls fastest, and whether to stop. measured: the "
      "fiducials so far, a vrreg.Measurements (its fiducial rows; noise_sd from their repeats) or "
      "(N, 3) sensor positions with measured_robot (N, 3) [m]; None: the first batch. The goal is "
      "goal_sd [m] or goal_floor_multiple times the noise floor sqrt(3 (sigma_rep^2 + "
      "noise_sd^2)); noise_sd [m] is one averaged fiducial reading's sd, sigma_opt / sqrt(K). "
      "interpolation: what the fiducials will be corrected with ('kriging', 'joint', 'rbf', "
      "'trilinear', 'auto'; not kriging: measured as a vrreg.Measurements): the goal and the "
      "stop judge its predicted sd at the parts (predicted_by).");

  m.def(
      "volume_part_points",
      [](const py::object& lower, const py::object& upper, double spacing) {
        const Eigen::Vector3d lo = vector_from(lower, "lower", 3);
        const Eigen::Vector3d hi = vector_from(upper, "upper", 3);
        std::vector<planning::PartPoint> parts = planning::volume_part_points(lo, hi, spacing);
        Points3 points(3, static_cast<Eigen::Index>(parts.size()));
        std::vector<std::string> names;
        for (std::size_t i = 0; i < parts.size(); ++i) {
          points.col(static_cast<Eigen::Index>(i)) = parts[i].robot_m;
          names.push_back(parts[i].name);
        }
        return py::make_tuple(to_numpy(std::move(points)), names);
      },
      py::arg("lower"), py::arg("upper"), py::arg("spacing") = 0.05,
      "Part points for a work volume, as `vrreg plan-next --volume`: a lattice of `spacing` [m] "
      "centred in the box lower..upper ((3,) each, METRES, robot base frame). Returns (parts "
      "(M, 3), names ['v1', ...]) for plan_next.");
}

}  // namespace vrreg::python
