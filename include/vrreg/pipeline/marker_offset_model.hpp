// SPDX-License-Identifier: Apache-2.0
#pragma once
// The marker offset a model was registered with (hand-eye registration, docs/hand-eye.md): where
// the marker sits on the flange and the robot whose forward kinematics puts it in the robot frame.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg {

/// An estimated marker offset: robot-frame positions are T_robot_flange(q) * p_flange_marker.
struct MarkerOffsetModel {
  Eigen::Vector3d p_flange_marker_m = Eigen::Vector3d::Zero();  ///< marker in the flange frame [m]
  Eigen::Vector3d p_std_m = Eigen::Vector3d::Zero();  ///< its standard uncertainty per axis [m]
  /// The robot up to its flange (base transform kept, tool removed): what the joints mean.
  kinematics::SerialChain flange_chain;

  /// The marker's position in the robot frame at joints `q_rad` [m].
  [[nodiscard]] Eigen::Vector3d marker_robot_m(const kinematics::JointRef& q_rad) const;
  /// The flange pose T_robot_flange at joints `q_rad` [m].
  [[nodiscard]] Eigen::Isometry3d flange_pose(const kinematics::JointRef& q_rad) const;
};

}  // namespace vrreg
