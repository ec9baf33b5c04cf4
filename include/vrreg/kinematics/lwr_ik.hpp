// SPDX-License-Identifier: Apache-2.0
#pragma once
// Closed-form IK of the KUKA LWR 4+ (7R, spherical shoulder and wrist) parametrised by the arm
// angle psi (Shimizu et al. 2008; Faria et al. 2018). Structure required (ChainFamily::kLwr):
// a = 0, d2 = d4 = d6 = 0, alpha = [pi/2, -pi/2, -pi/2, pi/2, pi/2, -pi/2, 0].
//
// Arm angle psi [rad]: rotation of the elbow about the shoulder-wrist axis u (right-handed about
// u, from shoulder S to wrist W), measured from the reference elbow: the one with theta3 = 0 and
// theta4 > 0 that reaches W with theta1 = atan2(W_y - S_y, W_x - S_x). All 8 global
// configurations (signs of theta2, theta4, theta6) of one (pose, psi) share the same elbow point.
#include <Eigen/Geometry>
#include <string>

#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Every global configuration reaching TCP pose `T_base_tcp` (base frame, m) with arm angle
/// `psi_rad`, within the joint limits when options.apply_joint_limits; at most 8.
IkResult lwr_inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                                double psi_rad, const IkOptions& options = {});

/// What a joint vector of an LWR-structured chain is: its pose, arm angle and configuration.
struct LwrArmState {
  Eigen::Isometry3d T_base_tcp = Eigen::Isometry3d::Identity();  ///< TCP pose, base frame (m)
  double psi_rad = 0.0;                                          ///< arm angle in (-pi, pi]
  ConfigurationLabel config{};  ///< global configuration (signs of theta2/4/6)
  std::uint8_t singular =
      kNoSingularity;  ///< Singularity flags (psi ill-defined if kElbowSingular)
};

/// The inverse of lwr_inverse_kinematics: pose, arm angle and configuration of `q_rad` [rad].
LwrArmState lwr_arm_state(const SerialChain& chain, const JointRef& q_rad,
                          double singular_tolerance = 1e-9);

/// The global configuration label of `q_rad` (signs of theta2, theta4, theta6; 0 counts as +).
ConfigurationLabel lwr_configuration(const SerialChain& chain, const JointRef& q_rad);

}  // namespace vrreg::kinematics
