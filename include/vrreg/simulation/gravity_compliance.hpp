// SPDX-License-Identifier: Apache-2.0
#pragma once
// Joint compliance under gravity: the deflection of each joint of a serial chain under the weight
// of the links it carries, dq_i = tau_i / k_i (a smooth, configuration-dependent error).
#include <vector>

#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::simulation {

/// Standard gravity [m/s^2], acting along -z of the robot base frame.
inline constexpr double kGravity_m_per_s2 = 9.80665;

/// Gravity torque about each joint axis at joints `q_rad` [N m]: link i of mass link_mass_kg[i]
/// lumped halfway between the origins of DH frames i-1 and i, `payload_kg` at the TCP.
kinematics::JointVector gravity_torques_nm(const kinematics::SerialChain& chain,
                                           const kinematics::JointRef& q_rad,
                                           const std::vector<double>& link_mass_kg,
                                           double payload_kg);

/// Joint deflection under gravity [rad]: tau_i / stiffness_i (stiffness in N m / rad).
kinematics::JointVector gravity_deflection_rad(const kinematics::SerialChain& chain,
                                               const kinematics::JointRef& q_rad,
                                               const std::vector<double>& link_mass_kg,
                                               double payload_kg,
                                               const std::vector<double>& stiffness_nm_per_rad);

}  // namespace vrreg::simulation
