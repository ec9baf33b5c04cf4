// SPDX-License-Identifier: Apache-2.0
#pragma once
// Data for the field-model tests: Gaussian-process draws and polynomial fields.
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "vrreg/core/random.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/correction/kriging.hpp"
#include "correction/field_basis.hpp"

namespace vrreg::testing {

/// Points uniform in the box [0, side_m)^3 (column per point).
inline Points3 uniform_box(Random& rng, int n, double side_m) {
  Points3 p(3, n);
  for (int j = 0; j < n; ++j) p.col(j) = Eigen::Vector3d(rng.uniform(), rng.uniform(), rng.uniform()) * side_m;
  return p;
}

/// One draw of the latent GP (zero mean, covariance of `hyper` without nugget) at `points_m`.
inline Eigen::VectorXd gp_draw(Random& rng, const Points3& points_m,
                               const KrigingHyperparameters& hyper, KrigingKernel kernel) {
  Eigen::MatrixXd k = detail::covariance(kernel, points_m, points_m, hyper);
  k.diagonal().array() += 1e-10 * hyper.signal_sd_m * hyper.signal_sd_m;  // draw jitter only
  const Eigen::LLT<Eigen::MatrixXd> llt(k);
  Eigen::VectorXd z(points_m.cols());
  for (Eigen::Index j = 0; j < z.size(); ++j) z(j) = rng.normal();
  return llt.matrixL() * z;
}

/// A fixed quadratic field per axis [m] of positions [m].
inline Points3 quadratic_field(const Points3& p) {
  Points3 v(3, p.cols());
  for (Eigen::Index j = 0; j < p.cols(); ++j) {
    const Eigen::Vector3d x = p.col(j);
    v.col(j) = 1e-3 * Eigen::Vector3d(0.2 + x.x() - 3 * x.y() * x.z() + 2 * x.x() * x.x(),
                                      -0.1 + 0.5 * x.z() + 4 * x.y() * x.y() - x.x() * x.y(),
                                      0.3 - x.y() + 2.5 * x.z() * x.z() + 1.5 * x.x() * x.z());
  }
  return v;
}

}  // namespace vrreg::testing
