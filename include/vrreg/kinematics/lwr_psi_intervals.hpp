// SPDX-License-Identifier: Apache-2.0
#pragma once
// Feasible arm angles of the KUKA LWR 4+ for one pose, per global configuration, under the joint
// limits (the analytic counterpart of Faria et al. 2018). psi as defined in lwr_ik.hpp.
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// A closed interval of arm angles [rad], lower <= upper, inside [-pi, pi].
struct PsiInterval {
  double lower_rad = 0.0;
  double upper_rad = 0.0;
};

/// Feasible arm angles of one pose, per global configuration (index = label index).
struct PsiIntervalsResult {
  IkStatus status = IkStatus::kUnreachable;
  std::string message{};
  /// For each configuration index 0..7 the sorted disjoint intervals where every joint is within
  /// its limits. A range across psi = pi appears as [.., pi] and [-pi, ..].
  std::array<std::vector<PsiInterval>, 8> intervals{};
  std::uint8_t singular = kNoSingularity;  ///< kElbowSingular / kArmAngleSingular of the pose
  [[nodiscard]] bool ok() const { return status == IkStatus::kOk; }
};

/// Feasible psi intervals under the joint limits, found analytically: every psi where a joint
/// meets a limit or theta2 / theta6 crosses 0 solves a*sin(psi) + b*cos(psi) + c = 0; between
/// consecutive roots feasibility is constant and is decided at the midpoint.
PsiIntervalsResult lwr_feasible_psi(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                                    const IkOptions& options = {});

}  // namespace vrreg::kinematics
