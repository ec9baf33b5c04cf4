// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/kriging_design.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "base_cylinder.hpp"
#include "field_basis.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

// Whitened cross terms of one query set: V = L^-1 k (J x N) and U = f - F' K^-1 k (terms x N).
struct Whitened {
  Eigen::MatrixXd v;
  Eigen::MatrixXd u;
};

struct Design {
  Eigen::LLT<Eigen::MatrixXd> k_llt;  ///< K = C + nugget I = L L'
  Eigen::MatrixXd l_inv_f;            ///< L^-1 F
  Eigen::LLT<Eigen::MatrixXd> a_llt;  ///< A = F' K^-1 F
  detail::TrendFrame frame;
};

Design condition(const ConstPoints3Ref& design_m, const KrigingDesignModel& model) {
  VRREG_THROW_UNLESS(model.trend_degree >= 0 && model.trend_degree <= 2,
                     "kriging design: trend degree " << model.trend_degree << " is not 0, 1 or 2");
  VRREG_THROW_UNLESS(design_m.allFinite(), "kriging design: non-finite fiducial position");
  const int terms = detail::trend_terms(model.trend_degree);
  VRREG_THROW_UNLESS(design_m.cols() >= terms,
                     "kriging design: " << design_m.cols()
                                        << " fiducials cannot determine a degree-"
                                        << model.trend_degree << " trend");
  const KrigingHyperparameters& h = model.hyperparameters;
  VRREG_THROW_UNLESS(h.length_m.allFinite() && (h.length_m.array() > 0.0).all() &&
                         std::isfinite(h.signal_sd_m) && h.signal_sd_m > 0.0 &&
                         std::isfinite(h.nugget_sd_m) && h.nugget_sd_m >= 0.0,
                     "kriging design: hyperparameters must be finite, length scales and signal sd "
                     "> 0, nugget sd >= 0");
  Design d;
  d.frame = detail::trend_frame(design_m);
  Eigen::MatrixXd k = detail::covariance(model.kernel, design_m, design_m, h);
  k.diagonal().array() += h.nugget_sd_m * h.nugget_sd_m;
  d.k_llt.compute(k);
  VRREG_THROW_UNLESS(
      d.k_llt.info() == Eigen::Success,
      "kriging design: covariance of " << design_m.cols() << " fiducials is not positive definite");
  d.l_inv_f = d.k_llt.matrixL().solve(detail::trend_basis(design_m, model.trend_degree, d.frame));
  d.a_llt.compute(d.l_inv_f.transpose() * d.l_inv_f);
  VRREG_THROW_UNLESS(d.a_llt.info() == Eigen::Success,
                     "kriging design: " << design_m.cols()
                                        << " fiducials cannot determine a degree-"
                                        << model.trend_degree << " trend (coplanar or collinear?)");
  return d;
}

Whitened whiten(const Design& d, const ConstPoints3Ref& design_m, const ConstPoints3Ref& query_m,
                const KrigingDesignModel& model) {
  Whitened w;
  w.v = d.k_llt.matrixL().solve(
      detail::covariance(model.kernel, design_m, query_m, model.hyperparameters));
  w.u = detail::trend_basis(query_m, model.trend_degree, d.frame).transpose() -
        d.l_inv_f.transpose() * w.v;
  return w;
}

}  // namespace

Eigen::MatrixXd kriging_posterior_covariance(const ConstPoints3Ref& design_m,
                                             const ConstPoints3Ref& a_m, const ConstPoints3Ref& b_m,
                                             const KrigingDesignModel& model) {
  const Design d = condition(design_m, model);
  const Whitened wa = whiten(d, design_m, a_m, model);
  const Whitened wb = whiten(d, design_m, b_m, model);
  return detail::covariance(model.kernel, a_m, b_m, model.hyperparameters) -
         wa.v.transpose() * wb.v + wa.u.transpose() * d.a_llt.solve(wb.u);
}

Eigen::VectorXd kriging_posterior_variance(const ConstPoints3Ref& design_m,
                                           const ConstPoints3Ref& query_m,
                                           const KrigingDesignModel& model) {
  const Design d = condition(design_m, model);
  const Whitened w = whiten(d, design_m, query_m, model);
  const Eigen::MatrixXd a_inv_u = d.a_llt.solve(w.u);
  const double signal_variance =
      model.hyperparameters.signal_sd_m * model.hyperparameters.signal_sd_m;
  Eigen::VectorXd variance(query_m.cols());
  for (Eigen::Index n = 0; n < query_m.cols(); ++n) {
    // Rounding can leave -1e-20 at a fiducial.
    variance(n) =
        std::max(signal_variance - w.v.col(n).squaredNorm() + w.u.col(n).dot(a_inv_u.col(n)), 0.0);
  }
  return variance;
}

int kriging_trend_degree_for(Eigen::Index n_fiducials) {
  return n_fiducials >= 100 ? 2 : n_fiducials >= 40 ? 1 : 0;
}

Points3 KrigingCorrectorDesign::inputs(const ConstPoints3Ref& robot_m) const {
  return cylinder ? cylinder->coordinates(robot_m) : Points3(robot_m);
}

KrigingCorrectorDesign fit_kriging_corrector_design(const SimilarityTransform& T_robot_sensor,
                                                    const ConstPoints3Ref& fiducials_robot_m,
                                                    const ConstPoints3Ref& corrections_sensor_m,
                                                    std::optional<double> noise_sd_m) {
  KrigingCorrectorDesign design;
  // The same frame, components and options as the kriging correction method (method_kriging).
  if (auto cylinder = detail::BaseCylinder::fit(fiducials_robot_m)) {
    design.cylinder = std::make_shared<const detail::BaseCylinder>(*cylinder);
  }
  const Points3 robot_frame = T_robot_sensor.rotation * corrections_sensor_m;
  const Points3 values =
      design.cylinder ? design.cylinder->to_local(fiducials_robot_m, robot_frame) : robot_frame;
  KrigingOptions options;
  options.noise_sd_m = noise_sd_m;
  options.trend_degree = kriging_trend_degree_for(fiducials_robot_m.cols());
  const KrigingModel model = KrigingModel::fit(design.inputs(fiducials_robot_m), values, options);
  for (std::size_t a = 0; a < 3; ++a) {
    design.axes[a] = {model.axes()[a].hyperparameters, options.kernel, options.trend_degree};
    design.latent_sd_scale[a] = model.axes()[a].latent_sd_scale;
  }
  return design;
}

}  // namespace vrreg
