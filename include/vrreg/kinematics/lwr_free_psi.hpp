// SPDX-License-Identifier: Apache-2.0
#pragma once
// LWR 4+ inverse kinematics with the arm angle left free: each global configuration at an arm
// angle where every joint is within its limits (lwr_psi_intervals.hpp), so that a pose reachable
// within the limits is never refused for the sake of one fixed psi.
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/lwr_psi_intervals.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// How far inside a feasible psi interval a free arm angle stays [rad]: a joint exactly on its
/// limit is one rounding away from outside it.
inline constexpr double kFreePsiMarginRad = 0.0174532925199432957;  // 1 deg

/// The arm angle a free pose takes among `feasible` (sorted, disjoint): 0 when it is feasible
/// with the margin, else the feasible psi nearest 0 kept kFreePsiMarginRad inside its interval
/// (an interval narrower than two margins: its middle); empty when there is none.
std::optional<double> free_arm_angle(const std::vector<PsiInterval>& feasible);

/// Every global configuration of `T_base_tcp` (base frame, m) that some arm angle brings within
/// the joint limits, each at its free_arm_angle; IkSolution::psi_rad says which. With
/// options.apply_joint_limits false every configuration is solved at psi = 0.
IkResult lwr_inverse_kinematics_free_psi(const SerialChain& chain,
                                         const Eigen::Isometry3d& T_base_tcp,
                                         const IkOptions& options = {});

}  // namespace vrreg::kinematics
