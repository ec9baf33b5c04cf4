// SPDX-License-Identifier: Apache-2.0
#pragma once
// Rotations as rotation vectors (the exponential and logarithm maps of SO(3)) and their mean on
// SO(3): what orientation residuals are interpolated on (the tangent space at the mean).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <span>

namespace vrreg {

/// R = exp([w]x): the rotation by |w| [rad] about w / |w| (Rodrigues); the identity for w = 0.
Eigen::Matrix3d rotation_exp(const Eigen::Vector3d& w_rad);

/// The rotation vector w of R (R = exp([w]x)), |w| in [0, pi] [rad]; accurate for small angles
/// (from the unit quaternion, not the trace). R must be a rotation.
Eigen::Vector3d rotation_log(const Eigen::Matrix3d& rotation);

/// The angle of the rotation taking `a` to `b`, |log(b a^T)| [rad] in [0, pi].
double rotation_angle_rad(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

/// The mean M of rotations R_j on SO(3) (the Karcher mean of the geodesic distance): the M with
/// sum_j log(R_j M^T) = 0, by Gauss-Newton from the chordal mean. Unique when all lie within
/// pi/2 of one another. Throws InputError when `rotations` is empty or not finite.
Eigen::Matrix3d rotation_mean(std::span<const Eigen::Matrix3d> rotations);

/// The mean of n unit quaternions q_r and their spread.
struct QuaternionMean {
  Eigen::Quaterniond mean{Eigen::Quaterniond::Identity()};
  /// Sum over the readings of the squared angle to the mean [rad^2] (to the second order).
  double sq_dev_rad2 = 0.0;
};

/// The mean from `sum_q_qT` = sum_r q_r q_r^T over n quaternions (coefficients x, y, z, w): its
/// dominant eigenvector (Markley et al. 2007, the rotation minimising the summed squared chordal
/// distances; q and -q count alike), with the sign of `sign_of`. The spread: sum_r (q . q_r)^2 =
/// sum_r cos^2(angle_r / 2) ~ n - sum_r angle_r^2 / 4 is the largest eigenvalue.
QuaternionMean quaternion_mean(const Eigen::Matrix4d& sum_q_qT, int n,
                               const Eigen::Quaterniond& sign_of);

}  // namespace vrreg
