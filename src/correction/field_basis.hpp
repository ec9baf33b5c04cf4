// SPDX-License-Identifier: Apache-2.0
#pragma once
// Building blocks shared by the field models (kriging, RBF): the polynomial trend basis and
// the stationary covariance functions with their length-scale derivatives.
#include <Eigen/Core>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/kriging.hpp"

namespace vrreg::detail {

/// Number of monomials of degree <= `degree` in 3 variables (1, 4, 10).
[[nodiscard]] int trend_terms(int degree);

/// Centre and scale that map positions to O(1) coordinates for a well-conditioned basis.
struct TrendFrame {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double scale_m = 1.0;
};
/// Centroid and largest bounding-box side (1 m if all points coincide).
[[nodiscard]] TrendFrame trend_frame(const ConstPoints3Ref& points_m);

/// N x terms matrix of monomials of u = (x - centre) / scale, degree <= `degree`.
[[nodiscard]] Eigen::MatrixXd trend_basis(const ConstPoints3Ref& points_m, int degree,
                                          const TrendFrame& frame);

/// Correlation rho(r^2) of the kernel at squared anisotropic distance r^2 (rho(0) = 1).
[[nodiscard]] double kernel_correlation(KrigingKernel kernel, double r2);
/// g(r^2) with d rho / d log(length_i) = g(r^2) (dx_i / length_i)^2.
[[nodiscard]] double kernel_length_factor(KrigingKernel kernel, double r2);

/// Covariance matrix s^2 rho(r^2(a_i, b_j)) between the columns of a and b (no nugget).
[[nodiscard]] Eigen::MatrixXd covariance(KrigingKernel kernel, const ConstPoints3Ref& a_m,
                                         const ConstPoints3Ref& b_m,
                                         const KrigingHyperparameters& hyper);

}  // namespace vrreg::detail
