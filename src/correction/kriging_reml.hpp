// SPDX-License-Identifier: Apache-2.0
#pragma once
// Restricted (REML) marginal log-likelihood of a universal-kriging model and its analytic
// gradient in log-parameters (docs/field-models.md, "Hyperparameters").
#include <Eigen/Core>
#include <array>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/kriging.hpp"

namespace vrreg::detail {

/// Everything the likelihood needs that does not depend on the hyperparameters.
struct RemlData {
  std::array<Eigen::MatrixXd, 3> squared_difference_m2;  ///< (x_a,i - x_b,i)^2 per axis i
  Eigen::VectorXd values;                                ///< y
  Eigen::MatrixXd trend;                                 ///< F, n x terms
  KrigingKernel kernel = KrigingKernel::matern52;
  double nugget_floor_variance = 0.0;  ///< known noise variance (units of y^2)
};
[[nodiscard]] RemlData make_reml_data(const ConstPoints3Ref& positions_m,
                                      const Eigen::VectorXd& values, const Eigen::MatrixXd& trend,
                                      KrigingKernel kernel, double nugget_floor_variance);

/// theta = (log l_x, log l_y, log l_z, log s, log e): length scales [m], signal sd, and the
/// nugget's excess sd e over the floor (nugget variance = floor + e^2).
using RemlParameters = Eigen::Matrix<double, 5, 1>;
[[nodiscard]] KrigingHyperparameters hyperparameters_from(const RemlParameters& theta,
                                                          double nugget_floor_variance);

/// log p_REML(y | theta) = -1/2 (y' P y + log|K| + log|F' K^-1 F| + (n - m) log 2 pi),
/// P = K^-1 - K^-1 F (F' K^-1 F)^-1 F' K^-1; gradient d/dtheta_k = 1/2 tr((P y y' P - P) dK_k).
/// Returns -infinity when K or F' K^-1 F is not positive definite.
[[nodiscard]] double restricted_log_likelihood(const RemlData& data, const RemlParameters& theta,
                                               RemlParameters* gradient);

}  // namespace vrreg::detail
