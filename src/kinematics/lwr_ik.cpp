// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/lwr_ik.hpp"

#include <algorithm>
#include <cmath>

#include "limits_fit.hpp"
#include "lwr_solver.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/pose.hpp"

namespace vrreg::kinematics {

IkResult lwr_inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                                double psi_rad, const IkOptions& options) {
  const detail::LwrGeometry g = detail::lwr_geometry(chain, "LWR inverse kinematics");
  options.validate();
  check_pose(T_base_tcp, "LWR inverse kinematics: target pose");
  VRREG_THROW_UNLESS(std::isfinite(psi_rad),
                     "LWR inverse kinematics: arm angle psi is not finite (" << psi_rad << ")");
  const Eigen::Isometry3d t = chain.dh0_flange_from_base_tcp(T_base_tcp);
  const detail::LwrPoseFrame frame = detail::lwr_pose_frame(
      g, t.linear(), t.translation(), options.singular_tolerance, options.reach_tolerance_m);
  IkResult result;
  if (!frame.reachable) {
    result.message = frame.message;
    return result;
  }
  const detail::LwrBaseSolution base = detail::lwr_base_solution(frame, psi_rad, options);
  result.singular = base.singular;
  // A singular joint collapses its two signs into one (the same configuration family).
  const int skip = ((base.singular & kShoulderSingular) != 0 ? 4 : 0) |
                   ((base.singular & kElbowSingular) != 0 ? 2 : 0) |
                   ((base.singular & kWristSingular) != 0 ? 1 : 0);
  result.solutions.reserve(8);
  double flipped[8][7];
  detail::lwr_flips(base.theta, flipped);
  int n_branches = 0;
  for (int index = 0; index < 8; ++index) {
    if ((index & skip) != 0) continue;
    ++n_branches;
    const double* const theta = flipped[index];
    // Default-initialised, then appended: emplace_back() would value-initialise it (zeroing all
    // of its fixed-size joint storage with a `rep stos`, a sixth of the call).
    IkSolution solution;
    JointVector& q = solution.q_rad;
    q.resize(7);
    bool inside = true;
    for (int i = 0; i < 7; ++i) {
      q(i) = g.offset[i] == 0.0 ? theta[i] : wrap_angle(theta[i] - g.offset[i]);
      if (options.apply_joint_limits && inside) {
        inside = detail::shift_joint(q(i), chain.limit(i), 0.0);
      }
    }
    if (!inside) {
      ++result.n_outside_limits;
      continue;
    }
    solution.config = ConfigurationLabel(ArmKind::kLwr, index);
    solution.singular = base.singular;
    result.solutions.push_back(solution);
  }
  if (result.solutions.empty()) {
    result.status = IkStatus::kOutsideLimits;
    result.message = "all " + std::to_string(n_branches) +
                     " configurations violate the joint limits at this arm angle";
  } else {
    result.status = IkStatus::kOk;
  }
  return result;
}

ConfigurationLabel lwr_configuration(const SerialChain& chain, const JointRef& q_rad) {
  const detail::LwrGeometry g = detail::lwr_geometry(chain, "LWR configuration");
  chain.check_joints(q_rad, "LWR configuration");
  const auto sign = [&](int i) { return wrap_angle(q_rad(i) + g.offset[i]) < 0.0 ? -1 : 1; };
  return ConfigurationLabel::lwr(sign(1), sign(3), sign(5));
}

LwrArmState lwr_arm_state(const SerialChain& chain, const JointRef& q_rad,
                          double singular_tolerance) {
  const detail::LwrGeometry g = detail::lwr_geometry(chain, "LWR arm angle");
  chain.check_joints(q_rad, "LWR arm angle");
  LwrArmState state;
  state.config = lwr_configuration(chain, q_rad);
  const Eigen::Isometry3d t = flange_in_dh0(chain, q_rad);
  state.T_base_tcp = chain.tcp_is_flange_in_dh0()
                         ? t
                         : Eigen::Isometry3d(chain.T_base_dh0() * t * chain.T_flange_tcp());
  const detail::LwrPoseFrame frame =
      detail::lwr_pose_frame(g, t.linear(), t.translation(), singular_tolerance, 1e-9);
  state.singular = frame.singular;
  double theta[7];
  for (int i = 0; i < 7; ++i) theta[i] = q_rad(i) + g.offset[i];
  if (std::abs(std::sin(theta[1])) <= singular_tolerance) state.singular |= kShoulderSingular;
  if (std::abs(std::sin(theta[3])) <= singular_tolerance) state.singular |= kElbowSingular;
  if (std::abs(std::sin(theta[5])) <= singular_tolerance) state.singular |= kWristSingular;
  if (!frame.reachable) return state;
  if ((state.singular & kElbowSingular) != 0) {
    // The elbow lies on the shoulder-wrist axis, so it does not tell psi; the shoulder frame does:
    // R03 = R_u(psi) R03_ref. An elbow flip turns R03 by pi about its y axis: undo it first (the
    // shoulder flip leaves R03 as it is).
    const double theta3 = theta[3] < 0.0 ? theta[2] - units::kPi : theta[2];
    const Eigen::Matrix3d r03 = detail::lwr_shoulder_rotation(theta[0], theta[1], theta3);
    const Eigen::Matrix3d m = r03 * frame.r03_reference.transpose();
    const Eigen::Vector3d axis_sin(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
    state.psi_rad = std::atan2(0.5 * frame.u.dot(axis_sin), 0.5 * (m.trace() - 1.0));
    return state;
  }
  // Elbow direction z2 = (-c1 s2, -s1 s2, c2); the reference elbow direction is -R03_ref col 1.
  const Eigen::Vector3d e(-std::cos(theta[0]) * std::sin(theta[1]),
                          -std::sin(theta[0]) * std::sin(theta[1]), std::cos(theta[1]));
  const Eigen::Vector3d e0 = -frame.r03_reference.col(1);
  const Eigen::Vector3d& u = frame.u;
  state.psi_rad = std::atan2(u.dot(e0.cross(e)), e0.dot(e) - u.dot(e0) * u.dot(e));
  return state;
}

}  // namespace vrreg::kinematics
