// SPDX-License-Identifier: Apache-2.0
#pragma once
// One entry point over the analytic solvers, chosen by the chain's family.
#include <Eigen/Geometry>
#include <optional>

#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Every IK solution of `T_base_tcp` (base frame, m): UR chains ignore `psi_rad`; LWR chains
/// solve at `psi_rad`, or without it each configuration at an arm angle within the joint limits
/// (lwr_free_psi.hpp); generic chains get the numerical IK (numeric_ik.hpp, default settings,
/// one solution per configuration class found).
IkResult inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                            std::optional<double> psi_rad = std::nullopt,
                            const IkOptions& options = {});

/// Controller-style choice among `all` (e.g. computed with apply_joint_limits = false): each
/// solution moved to the 2 pi shifts within the limits nearest `q_current_rad`, then the one with
/// the smallest joint travel in `norm`. A result with at most one solution.
IkResult nearest_solution(const SerialChain& chain, const IkResult& all,
                          const JointRef& q_current_rad, JointNorm norm = JointNorm::kL2);

/// The solution a controller moves to from `q_current_rad` [rad; m for prismatic joints]: every
/// branch without the limits, then nearest_solution. A generic chain's numerical IK starts from
/// the current joints, so that a redundant chain (an arm on a rail) answers the solution next to
/// them rather than one of its random starts'.
IkResult inverse_kinematics_nearest(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                                    const JointRef& q_current_rad,
                                    std::optional<double> psi_rad = std::nullopt,
                                    JointNorm norm = JointNorm::kL2);

/// The configuration label of `q_rad` [rad] (a generic chain's: signs of its branch joints).
std::optional<ConfigurationLabel> configuration_of(const SerialChain& chain, const JointRef& q_rad);

}  // namespace vrreg::kinematics
