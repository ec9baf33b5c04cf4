// SPDX-License-Identifier: Apache-2.0
#pragma once
// Forward kinematics and the geometric Jacobian as free functions of an immutable chain.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// 6 x n geometric Jacobian: rows 0-2 linear velocity [m/rad], rows 3-5 angular [rad/rad]
/// (a prismatic joint's column: [m/m] and 0).
using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, kMaxJoints>;

/// T_base_tcp: the TCP pose in the robot base frame at joints `q_rad` [rad; m for a prismatic
/// joint]; translation in m.
Eigen::Isometry3d forward_kinematics(const SerialChain& chain, const JointRef& q_rad);
/// T_dh0_flange: the flange (last DH frame) in the DH base frame, ignoring base and tool.
Eigen::Isometry3d flange_in_dh0(const SerialChain& chain, const JointRef& q_rad);
/// T_base_i for i = 0..n_rows(): frame 0 is the DH base, frame i follows DH row i; n_rows()+1
/// poses (m).
std::vector<Eigen::Isometry3d> link_frames(const SerialChain& chain, const JointRef& q_rad);
/// Geometric Jacobian of the TCP in the base frame: [v; w] = J(q) * dq, v of the TCP point; one
/// column per joint variable (a coupled variable's: its rows' columns times their multipliers).
Jacobian jacobian(const SerialChain& chain, const JointRef& q_rad);

}  // namespace vrreg::kinematics
