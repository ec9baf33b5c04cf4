// SPDX-License-Identifier: Apache-2.0
// Hand-eye registration (docs/hand-eye.md): T_robot_sensor and the marker's offset on the flange
// from joints and sensor positions (registration/marker_offset.hpp), for a built-in robot.
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/registration/marker_offset.hpp"

namespace vrreg::python {

void bind_hand_eye(py::module_& m) {
  m.def(
      "estimate_marker_offset",
      [](const std::string& robot, const py::object& joints, const py::object& sensor,
         double min_orientation_spread) {
        std::optional<kinematics::SerialChain> chain = kinematics::robot_by_name(robot);
        VRREG_THROW_UNLESS(chain, "unknown robot '" << robot << "' (ur3, ur5, ur10, ur5e, lwr4)");
        const kinematics::SerialChain flange = chain->with_tool(Eigen::Isometry3d::Identity());
        const Points3 y = points_from(sensor, "sensor");
        const Eigen::MatrixXd q = rows_from(joints, "joints", y.cols(), flange.n_joints());
        std::vector<Eigen::Isometry3d> poses;
        for (Eigen::Index j = 0; j < q.cols(); ++j) {
          poses.push_back(kinematics::forward_kinematics(flange, q.col(j)));
        }
        MarkerOffsetOptions options;
        options.min_orientation_spread = min_orientation_spread;
        MarkerOffsetResult r;
        {
          py::gil_scoped_release nogil;
          r = estimate_marker_offset(poses, y, options);
        }
        py::dict out;
        out["status"] = to_string(r.status);
        out["message"] = r.message;
        out["rotation"] = matrix_copy(r.T_robot_sensor.rotation);
        out["translation"] = vector_copy(r.T_robot_sensor.translation_m);
        out["p_flange_marker"] = vector_copy(r.p_flange_marker_m);
        out["p_std"] = vector_copy(r.p_std_m);
        out["translation_std"] = vector_copy(r.translation_std_m);
        out["fre"] = r.fre_m;
        out["orientation_spread"] = r.orientation_spread;
        out["condition_number"] = r.condition_number;
        return out;
      },
      py::arg("robot"), py::arg("joints"), py::arg("sensor"), py::kw_only(),
      py::arg("min_orientation_spread") = 0.02,
      R"doc(T_robot_sensor and the marker's position in the flange frame together (hand-eye,
docs/hand-eye.md): robot a built-in name ('ur5', 'lwr4', ...; its flange, no tool), joints (N, n)
[rad], sensor (N, 3) marker positions [m]. Returns a dict: status ('ok', 'unobservable',
'not-converged'), message, rotation (3, 3), translation (3,) [m], p_flange_marker (3,) [m], p_std
(3,) [m] (standard uncertainty per axis), translation_std, fre [m], orientation_spread [rad],
condition_number. Unobservable when the flange orientations do not vary about two axes.)doc");
}

}  // namespace vrreg::python
