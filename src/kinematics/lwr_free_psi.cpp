// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/lwr_free_psi.hpp"

#include <cmath>
#include <limits>

#include "vrreg/kinematics/lwr_ik.hpp"

namespace vrreg::kinematics {

std::optional<double> free_arm_angle(const std::vector<PsiInterval>& feasible) {
  std::optional<double> best;
  for (const PsiInterval& i : feasible) {
    const double margin = std::min(kFreePsiMarginRad, 0.5 * (i.upper_rad - i.lower_rad));
    const double lower = i.lower_rad + margin;
    const double upper = i.upper_rad - margin;
    const double psi = std::clamp(0.0, lower, upper);
    if (!best || std::abs(psi) < std::abs(*best)) best = psi;
  }
  return best;
}

IkResult lwr_inverse_kinematics_free_psi(const SerialChain& chain,
                                         const Eigen::Isometry3d& T_base_tcp,
                                         const IkOptions& options) {
  if (!options.apply_joint_limits) {
    IkResult r = lwr_inverse_kinematics(chain, T_base_tcp, 0.0, options);
    for (IkSolution& s : r.solutions) s.psi_rad = 0.0;
    return r;
  }
  const PsiIntervalsResult feasible = lwr_feasible_psi(chain, T_base_tcp, options);
  IkResult result;
  result.singular = feasible.singular;
  if (!feasible.ok()) {
    result.status = feasible.status;
    result.message = feasible.message;
    return result;
  }
  for (int c = 0; c < 8; ++c) {
    const std::optional<double> psi =
        free_arm_angle(feasible.intervals[static_cast<std::size_t>(c)]);
    if (!psi) {
      ++result.n_outside_limits;
      continue;
    }
    const IkResult at = lwr_inverse_kinematics(chain, T_base_tcp, *psi, options);
    result.singular |= at.singular;
    bool found = false;
    for (const IkSolution& s : at.solutions) {
      if (s.config.index() != c) continue;
      result.solutions.push_back(s);
      result.solutions.back().psi_rad = *psi;
      found = true;
    }
    // A singular pose folds configurations together: the one solved stands for its family.
    if (!found && (at.singular & (kShoulderSingular | kElbowSingular | kWristSingular)) == 0) {
      ++result.n_outside_limits;
    }
  }
  if (result.solutions.empty()) {
    result.status = IkStatus::kOutsideLimits;
    result.message = "no arm angle brings any configuration within the joint limits";
  } else {
    result.status = IkStatus::kOk;
  }
  return result;
}

}  // namespace vrreg::kinematics
