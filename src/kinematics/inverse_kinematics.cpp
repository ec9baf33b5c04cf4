// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/inverse_kinematics.hpp"

#include <limits>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/lwr_free_psi.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/numeric_ik.hpp"
#include "vrreg/kinematics/ur_ik.hpp"

namespace vrreg::kinematics {

IkResult inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                            std::optional<double> psi_rad, const IkOptions& options) {
  switch (chain.family()) {
    case ChainFamily::kUr:
      return ur_inverse_kinematics(chain, T_base_tcp, options);
    case ChainFamily::kLwr:
      if (!psi_rad) return lwr_inverse_kinematics_free_psi(chain, T_base_tcp, options);
      return lwr_inverse_kinematics(chain, T_base_tcp, *psi_rad, options);
    case ChainFamily::kGeneric:
      break;
  }
  options.validate();
  NumericIkOptions numeric;
  numeric.apply_joint_limits = options.apply_joint_limits;
  return numeric_inverse_kinematics(chain, T_base_tcp, numeric);
}

IkResult nearest_solution(const SerialChain& chain, const IkResult& all,
                          const JointRef& q_current_rad, JointNorm norm) {
  chain.check_joints(q_current_rad, "nearest IK solution: current joints");
  if (all.status != IkStatus::kOk) return all;
  IkResult result;
  result.singular = all.singular;
  result.n_outside_limits = all.n_outside_limits;
  double best = std::numeric_limits<double>::infinity();
  for (const IkSolution& s : all.solutions) {
    // The controller moves each joint to the 2 pi shift nearest its current value.
    const std::optional<JointVector> q = shift_nearest(chain, s.q_rad, q_current_rad);
    if (!q) {
      ++result.n_outside_limits;
      continue;
    }
    const JointVector travel = *q - q_current_rad;
    const double d = norm == JointNorm::kL2 ? travel.norm() : travel.cwiseAbs().maxCoeff();
    if (d < best) {
      best = d;
      result.solutions.assign(1, {*q, s.config, s.singular, s.psi_rad});
    }
  }
  if (result.solutions.empty()) {
    result.status = IkStatus::kOutsideLimits;
    result.message = "no solution has a 2 pi shift within the joint limits";
  } else {
    result.status = IkStatus::kOk;
  }
  return result;
}

IkResult inverse_kinematics_nearest(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                                    const JointRef& q_current_rad, std::optional<double> psi_rad,
                                    JointNorm norm) {
  chain.check_joints(q_current_rad, "nearest IK solution: current joints");
  IkOptions all;
  all.apply_joint_limits = false;
  switch (chain.family()) {
    case ChainFamily::kUr:
      return ur_inverse_kinematics_nearest(chain, T_base_tcp, q_current_rad, norm);
    case ChainFamily::kLwr:
      return nearest_solution(chain, inverse_kinematics(chain, T_base_tcp, psi_rad, all),
                              q_current_rad, norm);
    case ChainFamily::kGeneric:
      break;
  }
  NumericIkOptions numeric;
  numeric.apply_joint_limits = false;
  return nearest_solution(
      chain, numeric_inverse_kinematics(chain, T_base_tcp, numeric, JointVector(q_current_rad)),
      q_current_rad, norm);
}

std::optional<ConfigurationLabel> configuration_of(const SerialChain& chain,
                                                   const JointRef& q_rad) {
  switch (chain.family()) {
    case ChainFamily::kUr:
      return ur_configuration(chain, q_rad);
    case ChainFamily::kLwr:
      return lwr_configuration(chain, q_rad);
    case ChainFamily::kGeneric:
      break;
  }
  return generic_configuration(chain, q_rad);
}

}  // namespace vrreg::kinematics
