// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/pose.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vrreg/core/check.hpp"

namespace vrreg::kinematics {

Eigen::Matrix3d rotation_from_rpy(double roll_rad, double pitch_rad, double yaw_rad) {
  return (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d rpy_from_rotation(const Eigen::Matrix3d& r) {
  // R = Rz(y) Ry(p) Rx(r): first column (cp cy, cp sy, -sp), last row (., cp sr, cp cr).
  const double cos_pitch = std::hypot(r(0, 0), r(1, 0));
  const double pitch = std::atan2(-r(2, 0), cos_pitch);
  if (cos_pitch < 1e-12) {
    // Gimbal lock: only yaw -+ roll is defined; take roll = 0.
    const double yaw = std::atan2(-r(0, 1), r(1, 1));
    return {0.0, pitch + 0.0, yaw + 0.0};
  }
  // "+ 0.0" turns -0 into +0, so that printed angles never read "-0".
  return {std::atan2(r(2, 1), r(2, 2)) + 0.0, pitch + 0.0, std::atan2(r(1, 0), r(0, 0)) + 0.0};
}

double rotation_error(const Eigen::Matrix3d& rotation) {
  if (!rotation.allFinite() || !(rotation.determinant() > 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  return (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

void check_pose(const Eigen::Isometry3d& pose, const char* what, double tolerance) {
  VRREG_THROW_UNLESS(pose.translation().allFinite(),
                     what << ": translation is not finite: " << pose.translation().transpose());
  const Eigen::Matrix3d r = pose.linear();
  const double error = rotation_error(r);
  VRREG_THROW_UNLESS(error <= tolerance, what << ": not a rotation (max |R^T R - I| = " << error
                                              << ", det = " << r.determinant() << "; tolerance "
                                              << tolerance << ")");
  const auto bottom = pose.matrix().row(3);
  VRREG_THROW_UNLESS(bottom(0) == 0.0 && bottom(1) == 0.0 && bottom(2) == 0.0 && bottom(3) == 1.0,
                     what << ": last row of the homogeneous matrix is not [0 0 0 1]");
}

double rotation_angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  // Robust for small angles: the skew part gives sin, the trace gives cos.
  const Eigen::Matrix3d d = a.transpose() * b;
  const Eigen::Vector3d axis_sin(d(2, 1) - d(1, 2), d(0, 2) - d(2, 0), d(1, 0) - d(0, 1));
  const double s = 0.5 * axis_sin.norm();
  const double c = 0.5 * (d.trace() - 1.0);
  return std::atan2(s, std::clamp(c, -1.0, 1.0));
}

}  // namespace vrreg::kinematics
