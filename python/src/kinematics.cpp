// SPDX-License-Identifier: Apache-2.0
// Forward and inverse kinematics of the built-in arms (UR3/5/10/5e, KUKA LWR 4+) and of robot
// files (DH or URDF): TCP = flange unless a tool offset is given; every IK solution with its
// configuration label (analytic for UR and LWR chains, numerical for any other).
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "paths.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/robot_io/robot_file.hpp"

namespace vrreg::python {
namespace {

// A built-in name or a robot file (DH JSON/YAML, or URDF, between `base_link` and `tip_link`
// when given), as `--robot` with `--base-link` and `--tip-link` on the command line.
kinematics::SerialChain chain_named(const std::string& robot, const py::object& tool,
                                    const std::string& tip_link, const std::string& base_link) {
  const kinematics::SerialChain chain = io::load_robot(robot, {base_link, tip_link});
  if (tool.is_none()) return chain;
  const Eigen::VectorXd offset = vector_from(tool, "tool", 3);
  return chain.with_tool(Eigen::Isometry3d(Eigen::Translation3d(offset)));
}

Eigen::Isometry3d pose_from(const py::object& pose) {
  const py::array_t<double, py::array::forcecast> a =
      py::array_t<double, py::array::forcecast>::ensure(real_array(pose, "pose"));
  if (!a || a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4) {
    throw InputError("pose: expected a (4, 4) homogeneous matrix (translation in metres)");
  }
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (py::ssize_t r = 0; r < 3; ++r) {
    for (py::ssize_t c = 0; c < 4; ++c) t.matrix()(r, c) = a.at(r, c);
  }
  return t;
}

}  // namespace

void bind_kinematics(py::module_& m) {
  m.def(
      "fk",
      [](const PathText& robot, const py::object& q, const py::object& tool,
         const std::string& tip_link, const std::string& base_link) {
        const kinematics::SerialChain chain = chain_named(robot.text, tool, tip_link, base_link);
        const Eigen::VectorXd q_rad = vector_from(q, "q", chain.n_joints());
        return matrix_copy(kinematics::forward_kinematics(chain, q_rad).matrix());
      },
      py::arg("robot"), py::arg("q"), py::kw_only(), py::arg("tool") = py::none(),
      py::arg("tip_link") = "", py::arg("base_link") = "",
      "T_base_tcp (4, 4) at joints q [rad; m for a prismatic joint] of a built-in robot ('ur3', "
      "'ur5', 'ur10', 'ur5e', 'lwr4') or a robot file (DH JSON/YAML, or URDF); translation in "
      "METRES, base frame. tool: (3,) TCP offset in the flange frame [m]. tip_link, base_link: "
      "the URDF links the chain runs between (a URDF's mimic joints follow the joints they "
      "mimic: q holds the commanded joints only).");

  m.def(
      "ik",
      [](const PathText& robot, const py::object& pose, std::optional<double> psi,
         const py::object& tool, bool joint_limits, const std::string& tip_link,
         const std::string& base_link) {
        const kinematics::SerialChain chain = chain_named(robot.text, tool, tip_link, base_link);
        const Eigen::Isometry3d t = pose_from(pose);
        kinematics::IkOptions options;
        options.apply_joint_limits = joint_limits;
        const kinematics::IkResult r = kinematics::inverse_kinematics(chain, t, psi, options);
        Eigen::MatrixXd q(chain.n_joints(), static_cast<Eigen::Index>(r.solutions.size()));
        std::vector<std::string> labels;
        std::vector<int> indices;
        std::vector<std::string> singular;
        std::vector<std::optional<double>> psi_of;
        for (std::size_t s = 0; s < r.solutions.size(); ++s) {
          psi_of.push_back(r.solutions[s].psi_rad ? r.solutions[s].psi_rad : psi);
          q.col(static_cast<Eigen::Index>(s)) = r.solutions[s].q_rad;
          labels.push_back(r.solutions[s].config.to_string());
          indices.push_back(r.solutions[s].config.index());
          singular.push_back(kinematics::singularity_names(r.solutions[s].singular));
        }
        py::dict d;
        d["status"] = kinematics::to_string(r.status);
        d["message"] = r.message;
        d["q"] = columns_as_rows(q);
        d["configs"] = labels;
        d["config_indices"] = indices;
        d["singular"] = singular;
        if (chain.family() == kinematics::ChainFamily::kLwr) d["psi"] = psi_of;
        d["n_outside_limits"] = r.n_outside_limits;
        return d;
      },
      py::arg("robot"), py::arg("pose"), py::kw_only(), py::arg("psi") = py::none(),
      py::arg("tool") = py::none(), py::arg("joint_limits") = true, py::arg("tip_link") = "",
      py::arg("base_link") = "",
      "Every IK solution of TCP pose `pose` ((4, 4), translation in METRES, base frame) of a "
      "built-in robot or a robot file (analytic for UR and LWR chains; else numerical, one per "
      "configuration class found): a dict with q (S, n_joints) [rad], configs (labels such as "
      "'shoulder-left/elbow-up/wrist-noflip', 'GC=+,-,+' or 'q3+,q5-'), config_indices, "
      "singular, status "
      "('ok', 'unreachable', 'outside-limits') and message. psi: LWR 4+ arm angle [rad] "
      "(default: free, each configuration at 0 or the feasible arm angle nearest 0; LWR results "
      "add psi, each solution's [rad]); tool: (3,) TCP offset in the flange frame [m]; "
      "tip_link, base_link: as fk's.");
  m.def("robots", &kinematics::builtin_robot_names, "Names fk and ik accept.");
}

}  // namespace vrreg::python
