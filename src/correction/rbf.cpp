// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/rbf.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "point_index.hpp"
#include "rbf_loo.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {
namespace rbf_model {

void validate(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
              const RbfOptions& options) {
  VRREG_THROW_UNLESS(options.polynomial_degree == 1 || options.polynomial_degree == 2,
                     "rbf: polynomial degree must be 1 or 2 (r^3 needs a linear term), got "
                         << options.polynomial_degree);
  const int terms = detail::trend_terms(options.polynomial_degree);
  VRREG_THROW_UNLESS(positions_m.cols() == values_m.cols(),
                     "rbf: " << positions_m.cols() << " positions but " << values_m.cols()
                             << " values");
  VRREG_THROW_UNLESS(positions_m.cols() >= terms + 1,
                     "rbf: " << positions_m.cols() << " fiducials, a degree-"
                             << options.polynomial_degree << " polynomial needs at least "
                             << terms + 1);
  VRREG_THROW_UNLESS(positions_m.allFinite() && values_m.allFinite(),
                     "rbf: non-finite fiducial position or value");
  VRREG_THROW_UNLESS(
      options.exact_limit > terms && options.local_neighbours > terms &&
          (options.smoothing_block == 0 || options.smoothing_block > terms) &&
          options.n_smoothing >= 1 && options.min_log10_smoothing <= options.max_log10_smoothing,
      "rbf: exact_limit, local_neighbours and smoothing_block (unless 0) must exceed "
          << terms << ", n_smoothing >= 1, min <= max smoothing exponent");
  VRREG_THROW_UNLESS(!options.smoothing || (options.smoothing->allFinite() &&
                                            (options.smoothing->array() >= 0.0).all()),
                     "rbf: a given smoothing must be finite and >= 0");
}

}  // namespace rbf_model

struct RbfModel::Impl {
  Points3 positions_m;
  Points3 values_m;
  RbfOptions options;
  detail::TrendFrame frame;
  std::array<detail::RbfAxis, 3> axes;  ///< global weights (exact) or smoothing + LOO only
  std::optional<detail::PointIndex> index;

  [[nodiscard]] bool exact() const { return positions_m.cols() <= options.exact_limit; }
};

RbfModel::RbfModel(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RbfModel::~RbfModel() = default;
RbfModel::RbfModel(RbfModel&&) noexcept = default;
RbfModel& RbfModel::operator=(RbfModel&&) noexcept = default;

RbfModel RbfModel::fit(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
                       const RbfOptions& options) {
  rbf_model::validate(positions_m, values_m, options);
  auto impl = std::make_unique<Impl>();
  impl->positions_m = positions_m;
  impl->values_m = values_m;
  impl->options = options;
  impl->index.emplace(positions_m);
  const double extent_m = detail::trend_frame(positions_m).scale_m;
  const auto duplicate = impl->index->duplicate(1e-9 * extent_m);
  VRREG_THROW_UNLESS(!duplicate, "rbf: fiducials " << (duplicate ? duplicate->first : 0) << " and "
                                                   << (duplicate ? duplicate->second : 0)
                                                   << " share a position");
  if (options.smoothing && !impl->exact()) {
    // A local model with its smoothing given needs nothing global: each query solves its own.
    for (int axis = 0; axis < 3; ++axis) {
      detail::RbfAxis& a = impl->axes[static_cast<std::size_t>(axis)];
      a.smoothing = (*options.smoothing)(axis);
      a.loo_rms = std::numeric_limits<double>::quiet_NaN();
    }
    impl->frame = detail::trend_frame(positions_m);
    return RbfModel(std::move(impl));
  }
  // The smoothing is chosen on all fiducials, or above exact_limit on the block of the
  // smoothing_block fiducials nearest the centroid (same density, so lambda transfers).
  Points3 block = positions_m;
  Points3 block_values = values_m;
  if (!impl->exact()) {
    const Eigen::Index block_size =
        options.smoothing_block > 0 ? options.smoothing_block : options.exact_limit;
    const std::vector<Eigen::Index> near =
        impl->index->nearest_k(positions_m.rowwise().mean(), static_cast<std::size_t>(block_size));
    block.resize(3, static_cast<Eigen::Index>(near.size()));
    block_values.resize(3, block.cols());
    for (Eigen::Index k = 0; k < block.cols(); ++k) {
      block.col(k) = positions_m.col(near[static_cast<std::size_t>(k)]);
      block_values.col(k) = values_m.col(near[static_cast<std::size_t>(k)]);
    }
  }
  impl->frame = detail::trend_frame(block);
  const detail::RbfSpectrum spectrum(block, options.polynomial_degree, impl->frame);
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::VectorXd y = block_values.row(axis).transpose();
    if (options.smoothing) {
      impl->axes[static_cast<std::size_t>(axis)] = spectrum.solve(y, (*options.smoothing)(axis));
      continue;
    }
    double best_lambda = 0.0;
    double best_sse = std::numeric_limits<double>::infinity();
    for (int k = 0; k < options.n_smoothing; ++k) {
      const double exponent =
          options.n_smoothing == 1
              ? options.min_log10_smoothing
              : options.min_log10_smoothing + (options.max_log10_smoothing -
                                               options.min_log10_smoothing) *
                                                  k / (options.n_smoothing - 1);
      const double lambda = spectrum.scale() * std::pow(10.0, exponent);
      const double sse = spectrum.loo_residuals(y, lambda).squaredNorm();
      if (sse < best_sse) {
        best_sse = sse;
        best_lambda = lambda;
      }
    }
    impl->axes[static_cast<std::size_t>(axis)] = spectrum.solve(y, best_lambda);
  }
  return RbfModel(std::move(impl));
}

FieldPrediction RbfModel::predict(const ConstPoints3Ref& query_m) const {
  VRREG_THROW_UNLESS(query_m.allFinite(), "rbf: non-finite query point");
  const Impl& m = *impl_;
  const Eigen::Index n = query_m.cols();
  FieldPrediction out{Points3(3, n), cv_rms_m().replicate(1, n)};
  const int degree = m.options.polynomial_degree;
  if (m.exact()) {
    for (int axis = 0; axis < 3; ++axis) {
      out.mean_m.row(axis) = detail::evaluate_rbf(m.axes[static_cast<std::size_t>(axis)],
                                                  m.positions_m, degree, m.frame, query_m)
                                 .transpose();
    }
    return out;
  }
  tbb::parallel_for(Eigen::Index{0}, n, [&](Eigen::Index q) {
    const std::vector<Eigen::Index> near =
        m.index->nearest_k(query_m.col(q), static_cast<std::size_t>(m.options.local_neighbours));
    Points3 local(3, static_cast<Eigen::Index>(near.size()));
    Points3 local_values(3, local.cols());
    for (Eigen::Index k = 0; k < local.cols(); ++k) {
      local.col(k) = m.positions_m.col(near[static_cast<std::size_t>(k)]);
      local_values.col(k) = m.values_m.col(near[static_cast<std::size_t>(k)]);
    }
    const detail::TrendFrame frame = detail::trend_frame(local);
    for (int axis = 0; axis < 3; ++axis) {
      const detail::RbfAxis fit =
          detail::solve_rbf_direct(local, local_values.row(axis).transpose(), degree, frame,
                                   m.axes[static_cast<std::size_t>(axis)].smoothing);
      out.mean_m(axis, q) = detail::evaluate_rbf(fit, local, degree, frame, query_m.col(q))(0);
    }
  });
  VRREG_THROW_UNLESS(out.mean_m.allFinite(),
                     "rbf: a local neighbourhood cannot determine the polynomial (raise "
                     "local_neighbours)");
  return out;
}

Eigen::Vector3d RbfModel::cv_rms_m() const {
  return {impl_->axes[0].loo_rms, impl_->axes[1].loo_rms, impl_->axes[2].loo_rms};
}

Eigen::Vector3d RbfModel::smoothing() const {
  return {impl_->axes[0].smoothing, impl_->axes[1].smoothing, impl_->axes[2].smoothing};
}

bool RbfModel::exact() const { return impl_->exact(); }

std::string RbfModel::describe(CorrectionValues values) const {
  std::ostringstream out;
  out << "rbf (r^3, polynomial degree " << impl_->options.polynomial_degree << ") of "
      << impl_->positions_m.cols() << " fiducials, "
      << (impl_->exact() ? std::string("global")
                         : "local (" + std::to_string(impl_->options.local_neighbours) +
                               " nearest)")
      << "; LOO RMS " << cv_rms_m().transpose() * 1e3 << " " << milli_unit(values);
  return out.str();
}

}  // namespace vrreg

namespace vrreg {
namespace {

std::string rbf_key(int axis, const char* key) {
  constexpr const char* kNames[3] = {"x", "y", "z"};
  return std::string(kNames[axis]) + "." + key;
}

}  // namespace

void RbfModel::save(MethodState& state) const {
  const Impl& m = *impl_;
  state.put("polynomial_degree", m.options.polynomial_degree);
  state.put("exact_limit", static_cast<double>(m.options.exact_limit));
  state.put("local_neighbours", static_cast<double>(m.options.local_neighbours));
  state.put("frame_centre_m", Eigen::MatrixXd(m.frame.centre_m));
  state.put("frame_scale_m", m.frame.scale_m);
  for (int axis = 0; axis < 3; ++axis) {
    const detail::RbfAxis& a = m.axes[static_cast<std::size_t>(axis)];
    state.put(rbf_key(axis, "smoothing"), a.smoothing);
    state.put(rbf_key(axis, "loo_rms_m"), a.loo_rms);
    if (m.exact()) {
      state.put(rbf_key(axis, "weights"), Eigen::MatrixXd(a.weights));
      state.put(rbf_key(axis, "coefficients"), Eigen::MatrixXd(a.coefficients));
    }
  }
}

RbfModel RbfModel::restore(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
                           const MethodState& state) {
  RbfOptions options;
  options.polynomial_degree = static_cast<int>(state.integer("polynomial_degree", 1, 2));
  options.exact_limit = static_cast<Eigen::Index>(state.integer("exact_limit", 1, 1LL << 40));
  options.local_neighbours =
      static_cast<Eigen::Index>(state.integer("local_neighbours", 1, 1LL << 40));
  rbf_model::validate(positions_m, values_m, options);
  auto impl = std::make_unique<Impl>();
  impl->positions_m = positions_m;
  impl->values_m = values_m;
  impl->options = options;
  impl->index.emplace(positions_m);
  impl->frame.centre_m = state.array("frame_centre_m", 3, 1);
  impl->frame.scale_m = state.number("frame_scale_m");
  VRREG_THROW_UNLESS(impl->frame.scale_m > 0.0, "the saved rbf corrector's frame scale is not > 0");
  const Eigen::Index terms = detail::trend_terms(options.polynomial_degree);
  for (int axis = 0; axis < 3; ++axis) {
    detail::RbfAxis& a = impl->axes[static_cast<std::size_t>(axis)];
    a.smoothing = state.number(rbf_key(axis, "smoothing"));
    a.loo_rms = state.number(rbf_key(axis, "loo_rms_m"));
    if (impl->exact()) {
      a.weights = state.array(rbf_key(axis, "weights"), positions_m.cols(), 1);
      a.coefficients = state.array(rbf_key(axis, "coefficients"), terms, 1);
    }
  }
  return RbfModel(std::move(impl));
}

}  // namespace vrreg
