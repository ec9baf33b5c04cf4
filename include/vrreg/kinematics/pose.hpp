// SPDX-License-Identifier: Apache-2.0
#pragma once
// Pose helpers: roll-pitch-yaw angles and checks that a matrix is a rotation.
#include <Eigen/Geometry>

namespace vrreg::kinematics {

/// R = Rz(yaw) * Ry(pitch) * Rx(roll); angles [rad].
Eigen::Matrix3d rotation_from_rpy(double roll_rad, double pitch_rad, double yaw_rad);
/// (roll, pitch, yaw) [rad] with R = Rz(yaw) Ry(pitch) Rx(roll), pitch in [-pi/2, pi/2];
/// at pitch = +-pi/2 (gimbal lock) roll is set to 0.
Eigen::Vector3d rpy_from_rotation(const Eigen::Matrix3d& rotation);
/// Largest entry of |R^T R - I|, or infinity if R has a non-finite entry or det(R) <= 0.
double rotation_error(const Eigen::Matrix3d& rotation);
/// Throws InputError unless `pose` is finite with a proper rotation (to `tolerance`).
void check_pose(const Eigen::Isometry3d& pose, const char* what, double tolerance = 1e-6);
/// Angle of the rotation taking `a` to `b` [rad], in [0, pi].
double rotation_angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

}  // namespace vrreg::kinematics
