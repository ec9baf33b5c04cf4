// SPDX-License-Identifier: Apache-2.0
#include "rbf_loo.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg::detail {

Eigen::MatrixXd cubic_kernel(const ConstPoints3Ref& a_m, const ConstPoints3Ref& b_m) {
  Eigen::MatrixXd phi(a_m.cols(), b_m.cols());
  for (Eigen::Index j = 0; j < b_m.cols(); ++j) {
    for (Eigen::Index i = 0; i < a_m.cols(); ++i) {
      const double r = (a_m.col(i) - b_m.col(j)).norm();
      phi(i, j) = r * r * r;
    }
  }
  return phi;
}

RbfSpectrum::RbfSpectrum(const ConstPoints3Ref& positions_m, int degree, const TrendFrame& frame)
    : phi_(cubic_kernel(positions_m, positions_m)),
      basis_(trend_basis(positions_m, degree, frame)) {
  const Eigen::Index n = basis_.rows();
  const Eigen::Index m = basis_.cols();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(basis_);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
  const Eigen::VectorXd r_diagonal = qr.matrixQR().diagonal().head(m).cwiseAbs();
  VRREG_THROW_UNLESS(r_diagonal.minCoeff() > 1e-10 * std::sqrt(static_cast<double>(n)),
                     "rbf: the " << n << " fiducial positions cannot determine a degree-"
                                 << degree << " polynomial (coplanar or collinear?)");
  const Eigen::MatrixXd z = q.rightCols(n - m);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(z.transpose() * phi_ * z);
  // r^3 is conditionally positive definite of order 2: Z' Phi Z > 0 up to rounding.
  eigenvalues_ = eigen.eigenvalues().cwiseMax(0.0);
  g_ = z * eigen.eigenvectors();
}

Eigen::VectorXd RbfSpectrum::loo_residuals(const Eigen::VectorXd& values, double lambda) const {
  const Eigen::VectorXd inverse = (eigenvalues_.array() + lambda).inverse().matrix();
  const Eigen::VectorXd weights = g_ * inverse.cwiseProduct(g_.transpose() * values);
  const Eigen::VectorXd h_diagonal = g_.array().square().matrix() * inverse;
  return weights.cwiseQuotient(h_diagonal);
}

RbfAxis RbfSpectrum::solve(const Eigen::VectorXd& values, double lambda) const {
  const Eigen::VectorXd inverse = (eigenvalues_.array() + lambda).inverse().matrix();
  RbfAxis axis;
  axis.weights = g_ * inverse.cwiseProduct(g_.transpose() * values);
  axis.smoothing = lambda;
  // P c = y - (Phi + lambda I) w holds exactly; least squares recovers c.
  const Eigen::VectorXd rest = values - phi_ * axis.weights - lambda * axis.weights;
  axis.coefficients = basis_.householderQr().solve(rest);
  axis.loo_rms = std::sqrt(loo_residuals(values, lambda).squaredNorm() /
                           static_cast<double>(values.size()));
  return axis;
}

RbfAxis solve_rbf_direct(const ConstPoints3Ref& positions_m, const Eigen::VectorXd& values,
                         int degree, const TrendFrame& frame, double lambda) {
  const Eigen::MatrixXd basis = trend_basis(positions_m, degree, frame);
  const Eigen::Index n = basis.rows();
  const Eigen::Index m = basis.cols();
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n + m, n + m);
  system.topLeftCorner(n, n) = cubic_kernel(positions_m, positions_m);
  system.topLeftCorner(n, n).diagonal().array() += lambda;
  system.topRightCorner(n, m) = basis;
  system.bottomLeftCorner(m, n) = basis.transpose();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
  rhs.head(n) = values;
  const Eigen::VectorXd solution = system.partialPivLu().solve(rhs);
  RbfAxis axis;
  axis.weights = solution.head(n);
  axis.coefficients = solution.tail(m);
  axis.smoothing = lambda;
  return axis;
}

Eigen::VectorXd evaluate_rbf(const RbfAxis& axis, const ConstPoints3Ref& positions_m, int degree,
                             const TrendFrame& frame, const ConstPoints3Ref& query_m) {
  return cubic_kernel(query_m, positions_m) * axis.weights +
         trend_basis(query_m, degree, frame) * axis.coefficients;
}

}  // namespace vrreg::detail
