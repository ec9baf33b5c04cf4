// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/rotation.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg {

Eigen::Matrix3d rotation_exp(const Eigen::Vector3d& w_rad) {
  const double angle = w_rad.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, w_rad / angle).toRotationMatrix();
}

Eigen::Vector3d rotation_log(const Eigen::Matrix3d& rotation) {
  Eigen::Quaterniond q(rotation);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // the short way round: angle in [0, pi]
  const double s = q.vec().norm();
  if (s == 0.0) return Eigen::Vector3d::Zero();
  // angle = 2 atan2(|v|, w) keeps full relative precision as the angle goes to 0.
  return (2.0 * std::atan2(s, q.w()) / s) * q.vec();
}

double rotation_angle_rad(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return rotation_log(b * a.transpose()).norm();
}

Eigen::Quaterniond unit_quaternion(const Eigen::Vector4d& xyzw, const char* what) {
  VRREG_THROW_UNLESS(xyzw.allFinite(), what << ": a quaternion that is not finite");
  const double norm = xyzw.norm();
  VRREG_THROW_UNLESS(std::abs(norm - 1.0) <= kUnitQuaternionTolerance,
                     what << ": the quaternion's norm is " << norm << ", not 1 (within "
                          << kUnitQuaternionTolerance << "); give a unit quaternion (x, y, z, w)");
  const Eigen::Quaterniond q(xyzw(3), xyzw(0), xyzw(1), xyzw(2));
  // A quaternion already unit to rounding keeps its bits: the same orientation given twice (a
  // file's, then as arrays) gives the same numbers.
  return std::abs(norm - 1.0) <= kUnitQuaternionRounding ? q : q.normalized();
}

Eigen::Vector3d kuka_abc_deg(const Eigen::Matrix3d& r) {
  // R = Rz(A) Ry(B) Rx(C): r20 = -sin B, r00 = cos A cos B, r10 = sin A cos B, r21 = cos B sin C,
  // r22 = cos B cos C. atan2 of both components keeps every angle accurate, also near B = 90 deg.
  const double cos_b = std::hypot(r(0, 0), r(1, 0));
  const double b = std::atan2(-r(2, 0), cos_b);
  double a = 0.0;
  double c = 0.0;
  if (cos_b > 1e-12) {
    a = std::atan2(r(1, 0), r(0, 0));
    c = std::atan2(r(2, 1), r(2, 2));
  } else {  // gimbal lock: only A +- C is defined; C = 0
    a = std::atan2(-r(0, 1), r(1, 1));
  }
  return {units::rad_to_deg(a), units::rad_to_deg(b), units::rad_to_deg(c)};
}

Eigen::Matrix3d rotation_from_kuka_abc_deg(const Eigen::Vector3d& abc_deg) {
  return (Eigen::AngleAxisd(units::deg_to_rad(abc_deg(0)), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(units::deg_to_rad(abc_deg(1)), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(units::deg_to_rad(abc_deg(2)), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Matrix3d rotation_mean(std::span<const Eigen::Matrix3d> rotations) {
  VRREG_THROW_UNLESS(!rotations.empty(), "the mean of no rotations");
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (const Eigen::Matrix3d& r : rotations) {
    VRREG_THROW_UNLESS(r.allFinite(), "a rotation that is not finite");
    sum += r;
  }
  // Start: the rotation nearest the arithmetic mean (the chordal L2 mean).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  Eigen::Matrix3d mean = svd.matrixU() * d * svd.matrixV().transpose();
  // Gauss-Newton on the geodesic distance: converges quadratically for clustered rotations.
  constexpr int kMaxIterations = 50;
  const double n = static_cast<double>(rotations.size());
  for (int it = 0; it < kMaxIterations; ++it) {
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    for (const Eigen::Matrix3d& r : rotations) step += rotation_log(r * mean.transpose());
    step /= n;
    mean = rotation_exp(step) * mean;
    if (step.norm() < 1e-15) break;
  }
  return mean;
}

QuaternionMean quaternion_mean(const Eigen::Matrix4d& sum_q_qT, int n,
                               const Eigen::Quaterniond& sign_of) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(sum_q_qT);
  Eigen::Vector4d q = eig.eigenvectors().col(3);
  if (q.dot(sign_of.coeffs()) < 0.0) q = -q;
  QuaternionMean out;
  out.mean = Eigen::Quaterniond(q(3), q(0), q(1), q(2)).normalized();
  out.sq_dev_rad2 = std::max(0.0, 4.0 * (static_cast<double>(n) - eig.eigenvalues()(3)));
  return out;
}

}  // namespace vrreg
