// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/rotation.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"

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
