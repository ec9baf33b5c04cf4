// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/kriging.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "kriging_fit.hpp"
#include "kriging_loo.hpp"
#include "kriging_posterior.hpp"
#include "point_index.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {
namespace kriging_model {

void validate(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
              const KrigingOptions& options) {
  const int terms = detail::trend_terms(options.trend_degree);
  VRREG_THROW_UNLESS(positions_m.cols() == values_m.cols(),
                     "kriging: " << positions_m.cols() << " positions but " << values_m.cols()
                                 << " values");
  VRREG_THROW_UNLESS(positions_m.cols() >= terms + 1,
                     "kriging: " << positions_m.cols() << " fiducials, a degree-"
                                 << options.trend_degree << " trend needs at least "
                                 << terms + 1);
  VRREG_THROW_UNLESS(positions_m.allFinite() && values_m.allFinite(),
                     "kriging: non-finite fiducial position or value");
  VRREG_THROW_UNLESS(!options.noise_sd_m ||
                         (std::isfinite(*options.noise_sd_m) && *options.noise_sd_m >= 0.0),
                     "kriging: noise sd must be finite and >= 0");
  VRREG_THROW_UNLESS(options.exact_limit >= 1 && options.local_neighbours > terms &&
                         options.fit_subset > terms && options.fit_cluster >= 1 &&
                         options.restarts >= 1 &&
                         options.max_iterations >= 1,
                     "kriging: exact_limit >= 1, local_neighbours and fit_subset > "
                         << terms << ", fit_cluster, restarts and max_iterations >= 1 required");
  if (options.latent_sd_scale) {
    for (const double c : *options.latent_sd_scale) {
      VRREG_THROW_UNLESS(std::isfinite(c) && c > 0.0,
                         "kriging: latent sd scale " << c << " must be finite and > 0");
    }
  }
  const detail::TrendFrame frame = detail::trend_frame(positions_m);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(
      detail::trend_basis(positions_m, options.trend_degree, frame));
  VRREG_THROW_UNLESS(qr.rank() == terms,
                     "kriging: the " << positions_m.cols()
                                     << " fiducial positions cannot determine a degree-"
                                     << options.trend_degree
                                     << " trend (coplanar or collinear?)");
}

/// Queries predicted together in the exact model: bounds the J x block covariance.
constexpr Eigen::Index kQueryBlock = 256;

}  // namespace kriging_model

struct KrigingModel::Impl {
  Points3 positions_m;
  Points3 values_m;
  KrigingOptions options;
  std::array<KrigingAxisFit, 3> axes;
  detail::TrendFrame frame;
  std::array<std::optional<detail::KrigingPosterior>, 3> exact_posterior;
  std::optional<detail::PointIndex> index;  ///< local prediction above exact_limit
  /// Above exact_limit: the trend fitted once to all fiducials (least squares, terms x 3) and
  /// the values minus that trend, which the local models krige with a constant mean.
  Eigen::MatrixXd global_beta;
  Points3 residuals_m;

  [[nodiscard]] bool exact() const { return positions_m.cols() <= options.exact_limit; }

  void condition() {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      axes[axis].latent_sd_scale = options.latent_sd_scale ? (*options.latent_sd_scale)[axis] : 1.0;
    }
    if (exact()) {
      // Axes in parallel: the leave-one-out inverse is J^3 / 3 per axis.
      tbb::parallel_for(std::size_t{0}, std::size_t{3}, [&](std::size_t axis) {
        exact_posterior[axis] = detail::condition_kriging(
            positions_m, values_m.row(static_cast<Eigen::Index>(axis)).transpose(),
            axes[axis].hyperparameters, options.kernel, options.trend_degree, frame);
        if (!options.latent_sd_scale && options.loo_sd_calibration) {
          axes[axis].latent_sd_scale = detail::loo_latent_sd_scale(
              detail::leave_one_out(*exact_posterior[axis]),
              axes[axis].hyperparameters.nugget_sd_m);
        }
      });
    } else {
      index.emplace(positions_m);
      const Eigen::MatrixXd basis = detail::trend_basis(positions_m, options.trend_degree, frame);
      global_beta = basis.colPivHouseholderQr().solve(values_m.transpose());
      residuals_m = values_m - (basis * global_beta).transpose();
    }
  }

  /// Local kriging: the global trend plus ordinary kriging (constant mean) of the residuals
  /// of the `local_neighbours` nearest fiducials, global hyperparameters. Re-estimating a
  /// 10-term trend from a small neighbourhood would throw away most of its information.
  void predict_local(const Eigen::Vector3d& query_m, Eigen::Ref<Eigen::Vector3d> mean,
                     Eigen::Ref<Eigen::Vector3d> sd) const {
    const std::vector<Eigen::Index> near = index->nearest_k(
        query_m, static_cast<std::size_t>(options.local_neighbours));
    Points3 local(3, static_cast<Eigen::Index>(near.size()));
    Points3 local_values(3, local.cols());
    for (Eigen::Index k = 0; k < local.cols(); ++k) {
      local.col(k) = positions_m.col(near[static_cast<std::size_t>(k)]);
      local_values.col(k) = residuals_m.col(near[static_cast<std::size_t>(k)]);
    }
    const detail::TrendFrame local_frame = detail::trend_frame(local);
    const Eigen::RowVectorXd trend =
        detail::trend_basis(query_m, options.trend_degree, frame) * global_beta;
    for (int axis = 0; axis < 3; ++axis) {
      const detail::KrigingPosterior post = detail::condition_kriging(
          local, local_values.row(axis).transpose(),
          axes[static_cast<std::size_t>(axis)].hyperparameters, options.kernel, 0, local_frame);
      Eigen::RowVectorXd m(1);
      Eigen::RowVectorXd s(1);
      detail::predict_kriging(post, query_m, m, s);
      mean(axis) = trend(axis) + m(0);
      sd(axis) = axes[static_cast<std::size_t>(axis)].latent_sd_scale * s(0);
    }
  }
};

KrigingModel::KrigingModel(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
KrigingModel::~KrigingModel() = default;
KrigingModel::KrigingModel(KrigingModel&&) noexcept = default;
KrigingModel& KrigingModel::operator=(KrigingModel&&) noexcept = default;

KrigingModel KrigingModel::fit(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
                               const KrigingOptions& options) {
  kriging_model::validate(positions_m, values_m, options);
  auto impl = std::make_unique<Impl>();
  impl->positions_m = positions_m;
  impl->values_m = values_m;
  impl->options = options;
  impl->frame = detail::trend_frame(positions_m);
  const std::vector<Eigen::Index> subset = detail::seeded_cluster_subset(
      positions_m, options.fit_subset, options.fit_cluster, options.subset_seed);
  Points3 fit_positions(3, static_cast<Eigen::Index>(subset.size()));
  Points3 fit_values(3, fit_positions.cols());
  for (Eigen::Index k = 0; k < fit_positions.cols(); ++k) {
    fit_positions.col(k) = positions_m.col(subset[static_cast<std::size_t>(k)]);
    fit_values.col(k) = values_m.col(subset[static_cast<std::size_t>(k)]);
  }
  tbb::parallel_for(0, 3, [&](int axis) {
    impl->axes[static_cast<std::size_t>(axis)] = detail::fit_kriging_axis(
        fit_positions, fit_values.row(axis).transpose(), options, impl->frame);
  });
  for (int axis = 0; axis < 3; ++axis) {
    VRREG_THROW_UNLESS(std::isfinite(impl->axes[static_cast<std::size_t>(axis)]
                                         .restricted_log_likelihood),
                       "kriging: no positive-definite covariance found for axis " << axis);
  }
  impl->condition();
  return KrigingModel(std::move(impl));
}

KrigingModel KrigingModel::with_hyperparameters(
    const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
    const std::array<KrigingHyperparameters, 3>& hyperparameters, const KrigingOptions& options) {
  kriging_model::validate(positions_m, values_m, options);
  for (const KrigingHyperparameters& hyper : hyperparameters) {
    VRREG_THROW_UNLESS((hyper.length_m.array() > 0.0).all() && hyper.length_m.allFinite() &&
                           hyper.signal_sd_m > 0.0 && std::isfinite(hyper.signal_sd_m) &&
                           hyper.nugget_sd_m >= 0.0 && std::isfinite(hyper.nugget_sd_m),
                       "kriging: length scales and signal sd must be > 0, nugget sd >= 0");
  }
  auto impl = std::make_unique<Impl>();
  impl->positions_m = positions_m;
  impl->values_m = values_m;
  impl->options = options;
  impl->frame = detail::trend_frame(positions_m);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    impl->axes[axis].hyperparameters = hyperparameters[axis];
    impl->axes[axis].n_fit = 0;
  }
  impl->condition();
  return KrigingModel(std::move(impl));
}

FieldPrediction KrigingModel::predict(const ConstPoints3Ref& query_m) const {
  VRREG_THROW_UNLESS(query_m.allFinite(), "kriging: non-finite query point");
  const Eigen::Index n = query_m.cols();
  FieldPrediction out{Points3(3, n), Points3(3, n)};
  if (impl_->exact()) {
    for (Eigen::Index begin = 0; begin < n; begin += kriging_model::kQueryBlock) {
      const Eigen::Index count = std::min(kriging_model::kQueryBlock, n - begin);
      for (int axis = 0; axis < 3; ++axis) {
        detail::predict_kriging(*impl_->exact_posterior[static_cast<std::size_t>(axis)],
                                query_m.middleCols(begin, count),
                                out.mean_m.row(axis).segment(begin, count),
                                out.sd_m.row(axis).segment(begin, count));
      }
    }
    for (int axis = 0; axis < 3; ++axis)
      out.sd_m.row(axis) *= impl_->axes[static_cast<std::size_t>(axis)].latent_sd_scale;
    return out;
  }
  tbb::parallel_for(Eigen::Index{0}, n, [&](Eigen::Index q) {
    impl_->predict_local(query_m.col(q), out.mean_m.col(q), out.sd_m.col(q));
  });
  return out;
}

const std::array<KrigingAxisFit, 3>& KrigingModel::axes() const { return impl_->axes; }

Eigen::Vector3d KrigingModel::nugget_sd_m() const {
  return {impl_->axes[0].hyperparameters.nugget_sd_m, impl_->axes[1].hyperparameters.nugget_sd_m,
          impl_->axes[2].hyperparameters.nugget_sd_m};
}

bool KrigingModel::exact() const { return impl_->exact(); }

std::string KrigingModel::describe(CorrectionValues values) const {
  std::ostringstream out;
  out << "kriging ("
      << (impl_->options.kernel == KrigingKernel::matern52 ? "Matern 5/2" : "squared exponential")
      << ", trend degree " << impl_->options.trend_degree << ") of " << impl_->positions_m.cols()
      << " fiducials, "
      << (impl_->exact() ? std::string("exact")
                         : "local (" + std::to_string(impl_->options.local_neighbours) +
                               " nearest)");
  const char* names[] = {"x", "y", "z"};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const KrigingHyperparameters& h = impl_->axes[axis].hyperparameters;
    out << "; " << names[axis] << ": l = " << h.length_m(0) * 1e3 << " " << h.length_m(1) * 1e3
        << " " << h.length_m(2) * 1e3 << " mm, s = " << h.signal_sd_m * 1e3 << " "
        << milli_unit(values) << ", nugget = " << h.nugget_sd_m * 1e3 << " " << milli_unit(values);
    if (impl_->axes[axis].latent_sd_scale != 1.0)
      out << ", sd x " << impl_->axes[axis].latent_sd_scale;
  }
  return out.str();
}

}  // namespace vrreg

namespace vrreg {
namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

std::string axis_key(std::size_t axis, const char* key) {
  return std::string(kAxisNames[axis]) + "." + key;
}

}  // namespace

void KrigingModel::save(MethodState& state) const {
  const KrigingOptions& o = impl_->options;
  state.put("trend_degree", o.trend_degree);
  state.put_text("kernel", o.kernel == KrigingKernel::matern52 ? "matern52" : "squared_exponential");
  if (o.noise_sd_m) state.put("noise_sd_m", *o.noise_sd_m);
  state.put("exact_limit", static_cast<double>(o.exact_limit));
  state.put("local_neighbours", static_cast<double>(o.local_neighbours));
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const KrigingAxisFit& a = impl_->axes[axis];
    state.put(axis_key(axis, "length_m"), Eigen::MatrixXd(a.hyperparameters.length_m));
    state.put(axis_key(axis, "signal_sd_m"), a.hyperparameters.signal_sd_m);
    state.put(axis_key(axis, "nugget_sd_m"), a.hyperparameters.nugget_sd_m);
    state.put(axis_key(axis, "latent_sd_scale"), a.latent_sd_scale);
    state.put(axis_key(axis, "n_fit"), static_cast<double>(a.n_fit));
  }
}

KrigingModel KrigingModel::restore(const ConstPoints3Ref& positions_m,
                                   const ConstPoints3Ref& values_m, const MethodState& state) {
  KrigingOptions options;
  options.trend_degree = static_cast<int>(state.integer("trend_degree", 0, 2));
  const std::string& kernel = state.text("kernel");
  VRREG_THROW_UNLESS(kernel == "matern52" || kernel == "squared_exponential",
                     "the saved kriging corrector's kernel '" << kernel << "' is unknown");
  options.kernel =
      kernel == "matern52" ? KrigingKernel::matern52 : KrigingKernel::squared_exponential;
  if (state.has("noise_sd_m")) options.noise_sd_m = state.number("noise_sd_m");
  options.exact_limit = static_cast<Eigen::Index>(state.integer("exact_limit", 1, 1LL << 40));
  options.local_neighbours =
      static_cast<Eigen::Index>(state.integer("local_neighbours", 1, 1LL << 40));
  std::array<KrigingHyperparameters, 3> h;
  options.latent_sd_scale.emplace();
  for (std::size_t axis = 0; axis < 3; ++axis) {
    h[axis].length_m = state.array(axis_key(axis, "length_m"), 3, 1);
    h[axis].signal_sd_m = state.number(axis_key(axis, "signal_sd_m"));
    h[axis].nugget_sd_m = state.number(axis_key(axis, "nugget_sd_m"));
    (*options.latent_sd_scale)[axis] = state.number(axis_key(axis, "latent_sd_scale"));
  }
  KrigingModel out = with_hyperparameters(positions_m, values_m, h, options);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    out.impl_->axes[axis].n_fit =
        static_cast<Eigen::Index>(state.integer(axis_key(axis, "n_fit"), 0, 1LL << 40));
  }
  return out;
}

}  // namespace vrreg
