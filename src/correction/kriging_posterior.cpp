// SPDX-License-Identifier: Apache-2.0
#include "kriging_posterior.hpp"

#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg::detail {

KrigingPosterior condition_kriging(const ConstPoints3Ref& positions_m,
                                   const Eigen::VectorXd& values,
                                   const KrigingHyperparameters& hyper, KrigingKernel kernel,
                                   int degree, const TrendFrame& frame) {
  KrigingPosterior post;
  post.positions_m = positions_m;
  post.hyper = hyper;
  post.kernel = kernel;
  post.degree = degree;
  post.frame = frame;
  Eigen::MatrixXd k = covariance(kernel, positions_m, positions_m, hyper);
  k.diagonal().array() += hyper.nugget_sd_m * hyper.nugget_sd_m;
  post.k_llt.compute(k);
  VRREG_THROW_UNLESS(post.k_llt.info() == Eigen::Success,
                     "kriging: covariance of " << positions_m.cols()
                                               << " fiducials is not positive definite "
                                                  "(coincident fiducials need a nugget > 0)");
  const Eigen::MatrixXd f = trend_basis(positions_m, degree, frame);
  post.l_inv_f = post.k_llt.matrixL().solve(f);
  post.a_llt.compute(post.l_inv_f.transpose() * post.l_inv_f);
  VRREG_THROW_UNLESS(post.a_llt.info() == Eigen::Success,
                     "kriging: " << positions_m.cols() << " fiducials cannot determine a degree-"
                                 << degree << " trend (coplanar or collinear?)");
  const Eigen::VectorXd l_inv_y = post.k_llt.matrixL().solve(values);
  post.beta = post.a_llt.solve(post.l_inv_f.transpose() * l_inv_y);
  post.alpha = post.k_llt.solve(values - f * post.beta);
  return post;
}

void predict_kriging(const KrigingPosterior& post, const ConstPoints3Ref& query_m,
                     StridedRow mean, StridedRow sd) {
  const Eigen::MatrixXd k_star = covariance(post.kernel, post.positions_m, query_m, post.hyper);
  const Eigen::MatrixXd f_star = trend_basis(query_m, post.degree, post.frame);
  mean = (f_star * post.beta).transpose() + post.alpha.transpose() * k_star;
  const Eigen::MatrixXd v = post.k_llt.matrixL().solve(k_star);   // L^-1 k
  const Eigen::MatrixXd u = f_star.transpose() - post.l_inv_f.transpose() * v;  // f - F'K^-1 k
  const Eigen::MatrixXd a_inv_u = post.a_llt.solve(u);
  const double signal_variance = post.hyper.signal_sd_m * post.hyper.signal_sd_m;
  for (Eigen::Index n = 0; n < query_m.cols(); ++n) {
    const double variance =
        signal_variance - v.col(n).squaredNorm() + u.col(n).dot(a_inv_u.col(n));
    sd(n) = std::sqrt(std::max(variance, 0.0));  // rounding can leave -1e-20 at a fiducial
  }
}

}  // namespace vrreg::detail
