// SPDX-License-Identifier: Apache-2.0
#pragma once
// A serial chain given joint by joint, as URDF describes one (each joint's origin in its parent
// link's frame, then its motion about or along an axis), turned into the DH chain every
// kinematics function works on. The DH frames are placed on the joint axes (common normals; on
// parallel axes through the previous origin; x signs keeping |theta offset| <= 90 deg; frame 0's
// x the base's, or its opposite when only that gives a UR or LWR 4+ table), so a chain built like
// a UR or an LWR 4+ is recognised as one and gets its analytic IK.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "vrreg/kinematics/dh.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// One moving joint: T_parent_child(q) = T_parent_joint * Rot(axis, q) (or * Trans(axis q)).
struct ChainJoint {
  std::string name{};                                                ///< for messages
  JointType type = JointType::kRevolute;                             ///< revolute or prismatic
  Eigen::Isometry3d T_parent_joint = Eigen::Isometry3d::Identity();  ///< origin (m)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< in the joint frame, non-zero
  JointLimits limits{};                             ///< [rad], or [m] if prismatic
};

/// The DH chain with the kinematics of `joints`: T_base_tip(q) = T_base_joint1 * M1(q1) *
/// T_1_joint2 * M2(q2) * ... * Mn(qn) * T_joint_tip, with each joint's T_parent_joint the
/// transform from the previous joint's child frame (the first one's from the base frame; fixed
/// joints folded in). Base transform = DH frame 0 in the base frame, tool = the tip in the last
/// DH frame. Throws InputError on an empty list, a zero axis or bad limits.
SerialChain chain_from_joints(std::string name, const std::vector<ChainJoint>& joints,
                              const Eigen::Isometry3d& T_last_tip = Eigen::Isometry3d::Identity());

/// FK of `joints` composed directly as above (a reference for chain_from_joints) [m].
Eigen::Isometry3d joints_forward_kinematics(const std::vector<ChainJoint>& joints,
                                            const Eigen::Isometry3d& T_last_tip, const JointRef& q);

}  // namespace vrreg::kinematics
