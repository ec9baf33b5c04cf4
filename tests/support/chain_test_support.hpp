// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared by the tests of chains (kinematics, robot files): joint vectors within the limits, the
// gap between two poses, a urdfdom pose as a transform, and the Jacobian by central differences.
#include <Eigen/Geometry>
#include <algorithm>

#include "vrreg/core/random.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/pose.hpp"

namespace vrreg::testing {

/// Joint variables drawn uniformly within the chain's limits (SerialChain::limit) [rad; m].
inline kinematics::JointVector joints_within_limits(Random& rng,
                                                    const kinematics::SerialChain& chain) {
  kinematics::JointVector q(chain.n_joints());
  for (int i = 0; i < chain.n_joints(); ++i) {
    q(i) = rng.uniform(chain.limit(i).lower_rad, chain.limit(i).upper_rad);
  }
  return q;
}

/// The larger of the position gap [m] and the rotation angle [rad] between two poses.
inline double pose_gap(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return std::max((a.translation() - b.translation()).norm(),
                  kinematics::rotation_angle_between(a.linear(), b.linear()));
}

/// The TCP's geometric Jacobian (rows: velocity, angular velocity) by central differences of
/// step `h` in every joint variable.
inline Eigen::MatrixXd central_difference_jacobian(const kinematics::SerialChain& chain,
                                                   const kinematics::JointVector& q, double h) {
  Eigen::MatrixXd j(6, chain.n_joints());
  for (int i = 0; i < chain.n_joints(); ++i) {
    kinematics::JointVector qp = q, qm = q;
    qp(i) += h;
    qm(i) -= h;
    const Eigen::Isometry3d tp = kinematics::forward_kinematics(chain, qp);
    const Eigen::Isometry3d tm = kinematics::forward_kinematics(chain, qm);
    j.block<3, 1>(0, i) = (tp.translation() - tm.translation()) / (2 * h);
    j.block<3, 1>(3, i) = rotation_log(tp.linear() * tm.linear().transpose()) / (2 * h);
  }
  return j;
}

}  // namespace vrreg::testing
