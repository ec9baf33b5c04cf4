// SPDX-License-Identifier: Apache-2.0
#pragma once
// Closed-form IK of Universal Robots arms (UR3/5/10, e-Series): every solution, up to 8.
// Structure required (ChainFamily::kUr): alpha = [pi/2, 0, 0, pi/2, -pi/2, 0], a1 = a4 = a5 = a6 =
// 0 (d2 and d3 may be non-zero; theta offsets are allowed).
//
// Labels (geometric, so any joint vector has one): with h the reach of the wrist centre along x1
// in the arm plane, shoulder-right iff h * d4 > 0 (the wrist centre lies right of the upper arm,
// seen from above looking along the reach; q = 0 is shoulder-left); elbow-up iff the elbow (frame
// 2 origin) lies above the line from the shoulder to the wrist (frame 3 origin), i.e.
// x * (-a2 a3 sin theta3) > 0 with x the reach of frame 3 along x1 (x = 0 counts as positive);
// wrist-flip iff sin(theta5) < 0. Index bits: 4 shoulder-right, 2 elbow-down, 1 wrist-flip.
#include <Eigen/Geometry>

#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Every joint solution for the TCP pose `T_base_tcp` (base frame, m); joint values wrapped to
/// (-pi, pi] then shifted into the limits. At sin q5 ~ 0, q6 = options.singular_free_angle_rad.
IkResult ur_inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                               const IkOptions& options = {});

/// Controller-style single solution: over all branches and 2 pi shifts within the limits, the
/// joint vector nearest `q_current_rad` in `norm` (at a wrist singularity q6 = current q6);
/// joint limits always apply (options.apply_joint_limits is ignored).
IkResult ur_inverse_kinematics_nearest(const SerialChain& chain,
                                       const Eigen::Isometry3d& T_base_tcp,
                                       const JointRef& q_current_rad,
                                       JointNorm norm = JointNorm::kL2,
                                       const IkOptions& options = {});

/// The configuration label of joint vector `q_rad` [rad] of a UR-structured chain.
ConfigurationLabel ur_configuration(const SerialChain& chain, const JointRef& q_rad);

}  // namespace vrreg::kinematics
