// SPDX-License-Identifier: Apache-2.0
#pragma once
// Cubic RBF with a polynomial term on one set of fiducials: smoothing per axis by closed-form
// leave-one-out over a grid of smoothing values, then the weights (docs/field-models.md, "RBF").
#include <Eigen/Core>
#include <vector>

#include "field_basis.hpp"
#include "vrreg/core/types.hpp"

namespace vrreg::detail {

/// phi(r) = r^3, the 3D polyharmonic (triharmonic) spline.
[[nodiscard]] Eigen::MatrixXd cubic_kernel(const ConstPoints3Ref& a_m, const ConstPoints3Ref& b_m);

/// Weights w and polynomial coefficients c of s(x) = sum_j w_j phi(|x - x_j|) + p(x)' c.
struct RbfAxis {
  Eigen::VectorXd weights;
  Eigen::VectorXd coefficients;
  double smoothing = 0.0;  ///< lambda [m^3]
  double loo_rms = 0.0;    ///< leave-one-out RMS at lambda [units of the values]
};

/// Spectral form of the saddle-point system [Phi + lambda I, P; P', 0] on the null space Z of
/// P': Z' Phi Z = U D U', so every lambda costs O(n^2). Throws InputError if P has not full
/// column rank.
class RbfSpectrum {
 public:
  RbfSpectrum(const ConstPoints3Ref& positions_m, int degree, const TrendFrame& frame);
  /// Leave-one-out residuals at lambda (Rippa: e_i = w_i / (M^-1)_ii, valid with smoothing).
  [[nodiscard]] Eigen::VectorXd loo_residuals(const Eigen::VectorXd& values, double lambda) const;
  /// The fit at lambda.
  [[nodiscard]] RbfAxis solve(const Eigen::VectorXd& values, double lambda) const;
  /// Mean eigenvalue of Z' Phi Z: the natural unit of lambda.
  [[nodiscard]] double scale() const { return eigenvalues_.mean(); }

 private:
  Eigen::MatrixXd phi_;
  Eigen::MatrixXd basis_;   ///< P, n x m
  Eigen::MatrixXd g_;       ///< Z U, n x (n - m)
  Eigen::VectorXd eigenvalues_;
};

/// Solves the saddle-point system directly (small local neighbourhoods).
[[nodiscard]] RbfAxis solve_rbf_direct(const ConstPoints3Ref& positions_m,
                                       const Eigen::VectorXd& values, int degree,
                                       const TrendFrame& frame, double lambda);

/// s(query) for a fitted axis.
[[nodiscard]] Eigen::VectorXd evaluate_rbf(const RbfAxis& axis, const ConstPoints3Ref& positions_m,
                                           int degree, const TrendFrame& frame,
                                           const ConstPoints3Ref& query_m);

}  // namespace vrreg::detail
