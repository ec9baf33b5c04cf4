// SPDX-License-Identifier: Apache-2.0
#include "field_basis.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg::detail {

int trend_terms(int degree) {
  VRREG_THROW_UNLESS(degree >= 0 && degree <= 2,
                     "polynomial degree must be 0, 1 or 2, got " << degree);
  return degree == 0 ? 1 : (degree == 1 ? 4 : 10);
}

TrendFrame trend_frame(const ConstPoints3Ref& points_m) {
  TrendFrame frame;
  if (points_m.cols() == 0) {
    return frame;
  }
  frame.centre_m = points_m.rowwise().mean();
  const double side_m = (points_m.rowwise().maxCoeff() - points_m.rowwise().minCoeff()).maxCoeff();
  frame.scale_m = side_m > 0.0 ? side_m : 1.0;
  return frame;
}

Eigen::MatrixXd trend_basis(const ConstPoints3Ref& points_m, int degree, const TrendFrame& frame) {
  const int terms = trend_terms(degree);
  Eigen::MatrixXd basis(points_m.cols(), terms);
  for (Eigen::Index n = 0; n < points_m.cols(); ++n) {
    const Eigen::Vector3d u = (points_m.col(n) - frame.centre_m) / frame.scale_m;
    basis(n, 0) = 1.0;
    if (degree >= 1) {
      basis.block<1, 3>(n, 1) = u.transpose();
    }
    if (degree == 2) {
      basis.block<1, 6>(n, 4) << u.x() * u.x(), u.y() * u.y(), u.z() * u.z(), u.x() * u.y(),
          u.x() * u.z(), u.y() * u.z();
    }
  }
  return basis;
}

double kernel_correlation(KrigingKernel kernel, double r2) {
  if (kernel == KrigingKernel::squared_exponential) {
    return std::exp(-0.5 * r2);
  }
  const double a = std::sqrt(5.0 * r2);
  return (1.0 + a + a * a / 3.0) * std::exp(-a);
}

double kernel_length_factor(KrigingKernel kernel, double r2) {
  if (kernel == KrigingKernel::squared_exponential) {
    return std::exp(-0.5 * r2);
  }
  // d rho / dr * dr / d log l_i with dr / d log l_i = -(dx_i / l_i)^2 / r: no 1/r singularity.
  const double a = std::sqrt(5.0 * r2);
  return (5.0 / 3.0) * (1.0 + a) * std::exp(-a);
}

Eigen::MatrixXd covariance(KrigingKernel kernel, const ConstPoints3Ref& a_m,
                           const ConstPoints3Ref& b_m, const KrigingHyperparameters& hyper) {
  const Eigen::Vector3d inverse_length = hyper.length_m.cwiseInverse();
  const Eigen::Matrix3Xd a = inverse_length.asDiagonal() * a_m;
  const Eigen::Matrix3Xd b = inverse_length.asDiagonal() * b_m;
  const double variance = hyper.signal_sd_m * hyper.signal_sd_m;
  Eigen::MatrixXd result(a.cols(), b.cols());
  for (Eigen::Index j = 0; j < b.cols(); ++j) {
    for (Eigen::Index i = 0; i < a.cols(); ++i) {
      result(i, j) = variance * kernel_correlation(kernel, (a.col(i) - b.col(j)).squaredNorm());
    }
  }
  return result;
}

}  // namespace vrreg::detail
