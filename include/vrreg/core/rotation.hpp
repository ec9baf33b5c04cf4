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

/// How far from 1 a given quaternion's norm may be (rounded or single-precision input) before it
/// is refused rather than normalised.
inline constexpr double kUnitQuaternionTolerance = 1e-3;

/// Below this a quaternion's distance from norm 1 is rounding: it is used as given.
inline constexpr double kUnitQuaternionRounding = 1e-12;

/// The unit quaternion of coefficients `xyzw` (x, y, z, w), normalised (kept as given when unit
/// to kUnitQuaternionRounding). Throws InputError naming `what` when they are not finite or
/// their norm is not within kUnitQuaternionTolerance of 1.
Eigen::Quaterniond unit_quaternion(const Eigen::Vector4d& xyzw, const char* what);

/// KUKA's orientation angles of R: A, B, C [deg] with R = Rz(A) Ry(B) Rx(C) (a KRL FRAME or POS),
/// A and C in (-180, 180], B in [-90, 90]. At B = +-90 deg (A and C turn about the same axis) C is
/// set to 0 and A carries the turn.
Eigen::Vector3d kuka_abc_deg(const Eigen::Matrix3d& rotation);

/// R = Rz(A) Ry(B) Rx(C) from KUKA's A, B, C [deg].
Eigen::Matrix3d rotation_from_kuka_abc_deg(const Eigen::Vector3d& abc_deg);

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
