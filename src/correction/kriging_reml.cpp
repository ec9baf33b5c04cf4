// SPDX-License-Identifier: Apache-2.0
#include "kriging_reml.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <numbers>

#include "field_basis.hpp"

namespace vrreg::detail {

RemlData make_reml_data(const ConstPoints3Ref& positions_m, const Eigen::VectorXd& values,
                        const Eigen::MatrixXd& trend, KrigingKernel kernel,
                        double nugget_floor_variance) {
  RemlData data;
  const Eigen::Index n = positions_m.cols();
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::MatrixXd& d2 = data.squared_difference_m2[static_cast<std::size_t>(axis)];
    d2.resize(n, n);
    for (Eigen::Index b = 0; b < n; ++b) {
      for (Eigen::Index a = 0; a < n; ++a) {
        const double d = positions_m(axis, a) - positions_m(axis, b);
        d2(a, b) = d * d;
      }
    }
  }
  data.values = values;
  data.trend = trend;
  data.kernel = kernel;
  data.nugget_floor_variance = nugget_floor_variance;
  return data;
}

KrigingHyperparameters hyperparameters_from(const RemlParameters& theta,
                                            double nugget_floor_variance) {
  KrigingHyperparameters hyper;
  hyper.length_m = theta.head<3>().array().exp();
  hyper.signal_sd_m = std::exp(theta(3));
  hyper.nugget_sd_m = std::sqrt(nugget_floor_variance + std::exp(2.0 * theta(4)));
  return hyper;
}

double restricted_log_likelihood(const RemlData& data, const RemlParameters& theta,
                                 RemlParameters* gradient) {
  constexpr double kFailed = -std::numeric_limits<double>::infinity();
  const Eigen::Index n = data.values.size();
  const Eigen::Index m = data.trend.cols();
  const Eigen::Array3d inverse_length2 = (-2.0 * theta.head<3>()).array().exp();
  const double signal_variance = std::exp(2.0 * theta(3));
  const double excess_variance = std::exp(2.0 * theta(4));

  Eigen::MatrixXd r2 = inverse_length2(0) * data.squared_difference_m2[0];
  r2 += inverse_length2(1) * data.squared_difference_m2[1];
  r2 += inverse_length2(2) * data.squared_difference_m2[2];
  const Eigen::MatrixXd correlation =
      r2.unaryExpr([&](double v) { return kernel_correlation(data.kernel, v); });
  Eigen::MatrixXd k = signal_variance * correlation;
  k.diagonal().array() += data.nugget_floor_variance + excess_variance;

  const Eigen::LLT<Eigen::MatrixXd> llt(k);
  if (llt.info() != Eigen::Success) {
    return kFailed;
  }
  const Eigen::MatrixXd k_inv_f = llt.solve(data.trend);
  const Eigen::MatrixXd a = data.trend.transpose() * k_inv_f;
  const Eigen::LLT<Eigen::MatrixXd> a_llt(a);
  if (a_llt.info() != Eigen::Success) {
    return kFailed;
  }
  const Eigen::VectorXd k_inv_y = llt.solve(data.values);
  const Eigen::VectorXd beta = a_llt.solve(data.trend.transpose() * k_inv_y);
  const Eigen::VectorXd alpha = k_inv_y - k_inv_f * beta;  // P y

  const double log_det_k = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  const double log_det_a = 2.0 * a_llt.matrixLLT().diagonal().array().log().sum();
  const double value =
      -0.5 * (data.values.dot(alpha) + log_det_k + log_det_a +
              static_cast<double>(n - m) * std::log(2.0 * std::numbers::pi));
  if (!std::isfinite(value)) {
    return kFailed;
  }
  if (gradient == nullptr) {
    return value;
  }
  // W = P - alpha alpha'; dL/dtheta_k = -1/2 sum_ab W_ab (dK_k)_ab.
  Eigen::MatrixXd w = llt.solve(Eigen::MatrixXd::Identity(n, n));
  w.noalias() -= k_inv_f * a_llt.solve(k_inv_f.transpose());
  w.noalias() -= alpha * alpha.transpose();
  const Eigen::MatrixXd w_factor =
      w.cwiseProduct(r2.unaryExpr([&](double v) { return kernel_length_factor(data.kernel, v); }));
  for (int axis = 0; axis < 3; ++axis) {
    (*gradient)(axis) = -0.5 * signal_variance * inverse_length2(axis) *
                        w_factor.cwiseProduct(data.squared_difference_m2[static_cast<std::size_t>(axis)]).sum();
  }
  (*gradient)(3) = -signal_variance * w.cwiseProduct(correlation).sum();
  (*gradient)(4) = -excess_variance * w.trace();
  return value;
}

}  // namespace vrreg::detail
