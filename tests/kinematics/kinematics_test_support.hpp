// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers for the kinematics tests: random joint vectors and pose errors.
#include <Eigen/Geometry>

#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics::testing {

/// Joint vector uniform within the chain's limits [rad].
inline JointVector random_joints(Random& rng, const SerialChain& chain) {
  JointVector q(chain.n_joints());
  for (int i = 0; i < chain.n_joints(); ++i) {
    q(i) = rng.uniform(chain.limit(i).lower_rad, chain.limit(i).upper_rad);
  }
  return q;
}

/// Position error [m] and rotation error [rad] between two poses.
struct PoseError {
  double position_m;
  double rotation_rad;
};

inline PoseError pose_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return {(a.translation() - b.translation()).norm(),
          rotation_angle_between(a.linear(), b.linear())};
}

/// A fixed, generic TCP pose in front of the robot.
inline Eigen::Isometry3d pose_from(const Eigen::Vector3d& xyz_m, double roll, double pitch,
                                   double yaw) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotation_from_rpy(roll, pitch, yaw);
  t.translation() = xyz_m;
  return t;
}

/// A marker at `p_flange_m` (flange frame) in the robot base frame at joints `q` [m].
inline Eigen::Vector3d marker_at(const SerialChain& chain, const JointRef& q,
                                 const Eigen::Vector3d& p_flange_m) {
  return chain.T_base_dh0() * (flange_in_dh0(chain, q) * p_flange_m);
}

}  // namespace vrreg::kinematics::testing
