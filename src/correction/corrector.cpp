// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/corrector.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "buffers.hpp"
#include "method_support.hpp"
#include "method_tabulated.hpp"
#include "point_index.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/progress.hpp"
#include "vrreg/registration/fitzpatrick.hpp"

namespace vrreg {
namespace {

// A target's sd from the held-out errors of its 16 nearest fiducials (48 squared components, the
// RMS to about +-10 %): the errors vary over the volume, and one global RMS was pessimistic for
// the targets (simulated A1, trilinear: RMS of TRE/sd 0.80 with one global CV RMS, 0.84 local).
constexpr int kLocalCvNeighbours = 16;

// Batches below this run on the calling thread: the threads' start costs more than it saves.
constexpr Eigen::Index kSerialBelow = 8192;

// Whether a target's sd is the RMS of its nearest fiducials' held-out errors (else one global CV
// RMS). Not for the joint model: its held-out errors depend on which joint angles the training
// fiducials share with the held-out one, not on where it is, and near a target they can be much
// smaller than at it (27-fiducial cube, 10 seeds: RMS of TRE/sd 0.43 global, 2.95 local).
SdSource cv_sd_source(InterpolationMethod method) {
  return method == InterpolationMethod::kJoint ? SdSource::kGlobalCv : SdSource::kLocalCv;
}

MethodSettings method_settings(const InterpolationSettings& s,
                               const std::optional<kinematics::JointNorm>& nearest) {
  return {s.cube_edge_m, s.match_tolerance_m, nearest};
}

const Points3& no_points() {
  static const Points3 none(3, 0);
  return none;
}

const Eigen::MatrixXd& no_joints() {
  static const Eigen::MatrixXd none(0, 0);
  return none;
}

}  // namespace

void CorrectorOptions::validate() const {
  interpolation.validate();
  VRREG_THROW_UNLESS(cv_folds >= 2, "cross-validation needs at least 2 folds, got " << cv_folds);
  VRREG_THROW_UNLESS(!nearest_configuration ||
                         interpolation.method == InterpolationMethod::kOctuplet,
                     "the nearest-configuration stencil (Strategy 3) is an octuplet, not "
                         << to_string(interpolation.method));
}

CorrectionQuery::CorrectionQuery(const ConstPoints3Ref& sensor_m_)
    : CorrectionQuery(sensor_m_, no_points(), no_joints()) {}

CorrectionQuery::CorrectionQuery(const ConstPoints3Ref& sensor_m_,
                                 const ConstPoints3Ref& robot_nominal_m_,
                                 const Eigen::Ref<const Eigen::MatrixXd>& joints_rad_,
                                 std::span<const std::size_t> sequence_)
    : sensor_m(sensor_m_),
      robot_nominal_m(robot_nominal_m_),
      joints_rad(joints_rad_),
      sequence(sequence_) {}

struct Corrector::Impl {
  std::unique_ptr<const FittedMethod> fitted;
  SimilarityTransform T_robot_sensor;
  InterpolationSettings requested;
  std::optional<kinematics::JointNorm> nearest_configuration;
  int cv_folds = 5;
  std::uint64_t cv_seed = 1;
  bool tabulated = false;
  std::optional<CrossValidation> cross_validation;
  SdSource sd_source = SdSource::kNone;
  double cv_rms_m = 0.0;
  Eigen::VectorXd cv_squared_error_m2;  ///< per fiducial, NaN where not predicted (kLocalCv)
  /// kLocalCv: the fiducials with a held-out error, indexed, and their errors in that order.
  std::optional<detail::PointIndex> known_index;
  /// Extrapolation (CorrectionQuery::extrapolate): the field's gradient, the median over the
  /// fiducials of |d correction| / |d position| to the nearest fiducial, and its spread,
  /// sqrt(2) x the RMS (3D) of the corrections about their mean: the RMS difference of the
  /// field at two points too far apart to be correlated [m].
  double field_gradient = 0.0;
  double field_spread_m = 0.0;
  /// The registration's own error grows with the distance from the fiducials (its rotation's
  /// lever arm, Fitzpatrick's TRE): the fiducials' positions and their localisation error
  /// <FLE^2> [m^2], from the known noise, else half the median squared correction difference of
  /// nearest neighbours (noise and the field's change over a spacing).
  Points3 fiducials_robot_m;
  double fle_sq_m2 = 0.0;

  void field_scales(const CorrectorData& data) {
    const Eigen::Index n = data.size();
    const Eigen::Vector3d mean_m = data.corrections_sensor_m.rowwise().mean();
    field_spread_m = std::sqrt(2.0 * (data.corrections_sensor_m.colwise() - mean_m).squaredNorm() /
                               static_cast<double>(std::max<Eigen::Index>(n, 1)));
    const detail::PointIndex index(data.fiducials_robot_m);
    std::vector<double> ratio;
    std::vector<double> difference_sq;
    for (Eigen::Index j = 0; j < n; ++j) {
      const std::vector<Eigen::Index> two = index.nearest_k(data.fiducials_robot_m.col(j), 2);
      if (two.size() < 2) continue;
      const double d_m = (data.fiducials_robot_m.col(two[1]) - data.fiducials_robot_m.col(j)).norm();
      if (d_m <= 0.0) continue;
      const double difference_m =
          (data.corrections_sensor_m.col(two[1]) - data.corrections_sensor_m.col(j)).norm();
      ratio.push_back(difference_m / d_m);
      difference_sq.push_back(difference_m * difference_m);
    }
    if (ratio.empty()) return;
    const auto mid = ratio.begin() + static_cast<std::ptrdiff_t>(ratio.size() / 2);
    std::nth_element(ratio.begin(), mid, ratio.end());
    field_gradient = *mid;
    const auto mid_sq = difference_sq.begin() + static_cast<std::ptrdiff_t>(difference_sq.size() / 2);
    std::nth_element(difference_sq.begin(), mid_sq, difference_sq.end());
    fiducials_robot_m = data.fiducials_robot_m;
    fle_sq_m2 = data.noise_sd_m ? 3.0 * *data.noise_sd_m * *data.noise_sd_m : 0.5 * *mid_sq;
  }

  /// The sd of the correction at `edge_m` (sd `sd_edge_m` there) used at `at_m`, `moved_m`
  /// beyond the support: the field's change over the distance, up to its spread, and the
  /// registration's growth from the edge to the point.
  [[nodiscard]] double extrapolated_sd_m(double sd_edge_m, double moved_m, const Eigen::Vector3d& at_m,
                                         const Eigen::Vector3d& edge_m) const {
    // A move without a length (a joint clamped into its range) takes the whole spread.
    const double growth_m =
        std::isfinite(moved_m) ? std::min(field_gradient * moved_m, field_spread_m) : field_spread_m;
    const double registration_sq_m2 =
        std::max(0.0, expected_tre_squared(fiducials_robot_m, at_m, fle_sq_m2) -
                          expected_tre_squared(fiducials_robot_m, edge_m, fle_sq_m2));
    // Outside the joint ranges (another arm configuration) the robot's errors are not those the
    // registration absorbed: the rigid fit of the cell's systematic field tilts the mapping, and
    // nothing measured bounds the difference. Its growth is Fitzpatrick's with a localisation
    // error common to all fiducials (one independent sample, not N) whose mean square is the
    // spread's: the difference of two draws of the field, the one absorbed and the one met there.
    double tilt_sq_m2 = 0.0;
    if (!std::isfinite(moved_m)) {
      const Eigen::Vector3d centroid_m = fiducials_robot_m.rowwise().mean();
      const double variance_m2 = field_spread_m * field_spread_m;
      const auto n = static_cast<double>(fiducials_robot_m.cols());
      tilt_sq_m2 = n * std::max(0.0, expected_tre_squared(fiducials_robot_m, at_m, variance_m2) -
                                         expected_tre_squared(fiducials_robot_m, centroid_m, variance_m2));
    }
    return std::sqrt(sd_edge_m * sd_edge_m + growth_m * growth_m + registration_sq_m2 + tilt_sq_m2);
  }
  Eigen::VectorXd known_squared_m2;

  /// The index of the fiducials whose held-out error is known (kLocalCv).
  void index_known(const CorrectorData& data) {
    if (sd_source != SdSource::kLocalCv || fitted->has_own_sd()) return;
    VRREG_THROW_UNLESS(cv_squared_error_m2.size() == data.size(),
                       "the corrector has " << cv_squared_error_m2.size()
                                            << " held-out errors for " << data.size()
                                            << " fiducials");
    std::vector<Eigen::Index> known;
    for (Eigen::Index j = 0; j < data.size(); ++j) {
      if (std::isfinite(cv_squared_error_m2(j))) known.push_back(j);
    }
    VRREG_THROW_UNLESS(!known.empty(), "the corrector's cross-validation predicted no fiducial");
    Points3 known_m(3, static_cast<Eigen::Index>(known.size()));
    known_squared_m2.resize(known_m.cols());
    for (std::size_t i = 0; i < known.size(); ++i) {
      known_m.col(static_cast<Eigen::Index>(i)) = data.registered_robot_m.col(known[i]);
      known_squared_m2(static_cast<Eigen::Index>(i)) = cv_squared_error_m2(known[i]);
    }
    known_index.emplace(known_m);
  }

  /// The fitted method's corrections and sd at registered positions `at` (for a table).
  void exact_predictions(const Points3& at, Points3& corrections, Eigen::VectorXd& sd) const {
    const Eigen::Index n = at.cols();
    MethodPredictions p;
    p.corrections_sensor_m.resize(3, n);
    p.stencils.resize(static_cast<std::size_t>(n));
    if (fitted->has_own_sd()) p.sd_m.resize(n);
    const Points3 none(3, 0);
    const Eigen::MatrixXd no_joints(0, 0);
    const MethodQuery query{at, none, no_joints, {}, true};
    const Eigen::Index block = std::max<Eigen::Index>(fitted->block_size(), 1);
    for (Eigen::Index begin = 0; begin < n; begin += block) {
      fitted->predict(query, begin, std::min(n, begin + block), p);
    }
    corrections = std::move(p.corrections_sensor_m);
    sd.resize(sd_source == SdSource::kNone ? 0 : n);
    for (Eigen::Index i = 0; i < sd.size(); ++i) {
      sd(i) = fitted->has_own_sd()                 ? p.sd_m(i)
              : sd_source == SdSource::kLocalCv    ? local_sd_m(at.col(i))
                                                   : cv_rms_m;
    }
  }

  /// Corrects the points of `out` outside the support (CorrectionQuery::extrapolate).
  void extrapolate(const CorrectionQuery& query, TargetCorrection& out) const {
    std::vector<Eigen::Index> outside;
    for (std::size_t i = 0; i < out.stencils.size(); ++i) {
      if (out.stencils[i].status == StencilStatus::kOutsideSupport)
        outside.push_back(static_cast<Eigen::Index>(i));
    }
    const auto k = static_cast<Eigen::Index>(outside.size());
    if (k == 0) return;
    Points3 at_m(3, k);
    const bool joints = query.joints_rad.cols() == query.sensor_m.cols() && query.joints_rad.size() > 0;
    Eigen::MatrixXd q_rad(joints ? query.joints_rad.rows() : 0, joints ? k : 0);
    for (Eigen::Index j = 0; j < k; ++j) {
      at_m.col(j) = out.uncorrected_robot_m.col(outside[static_cast<std::size_t>(j)]);
      if (joints) q_rad.col(j) = query.joints_rad.col(outside[static_cast<std::size_t>(j)]);
    }
    const std::optional<Eigen::VectorXd> moved_m = fitted->clamp_to_support(at_m, q_rad);
    if (!moved_m) return;
    MethodPredictions p;
    p.corrections_sensor_m.resize(3, k);
    p.stencils.resize(static_cast<std::size_t>(k));
    if (fitted->has_own_sd()) p.sd_m.resize(k);
    const Points3 none(3, 0);
    const MethodQuery edge{at_m, none, q_rad, {}};
    const Eigen::Index block = std::max<Eigen::Index>(fitted->block_size(), 1);
    for (Eigen::Index begin = 0; begin < k; begin += block)
      fitted->predict(edge, begin, std::min(k, begin + block), p);
    for (Eigen::Index j = 0; j < k; ++j) {
      if (p.stencils[static_cast<std::size_t>(j)].status != StencilStatus::kOk) continue;
      const Eigen::Index i = outside[static_cast<std::size_t>(j)];
      out.stencils[static_cast<std::size_t>(i)].status = StencilStatus::kExtrapolated;
      out.corrections_sensor_m.col(i) = p.corrections_sensor_m.col(j);
      out.corrected_sensor_m.col(i) = query.sensor_m.col(i) + p.corrections_sensor_m.col(j);
      out.corrected_robot_m.col(i) = T_robot_sensor.apply(Eigen::Vector3d(out.corrected_sensor_m.col(i)));
      if (out.predicted_sd_m.size() > 0) {
        const double sd_edge_m = fitted->has_own_sd()                 ? p.sd_m(j)
                                 : sd_source == SdSource::kLocalCv ? local_sd_m(at_m.col(j))
                                                                   : cv_rms_m;
        out.predicted_sd_m(i) = extrapolated_sd_m(sd_edge_m, (*moved_m)(j),
                                                  out.uncorrected_robot_m.col(i), at_m.col(j));
      }
      --out.n_flagged;
    }
  }

  /// sqrt of the mean held-out squared error of the fiducials nearest `point_robot_m`.
  [[nodiscard]] double local_sd_m(const Eigen::Vector3d& point_robot_m) const {
    const std::vector<Eigen::Index> near =
        known_index->nearest_k(point_robot_m, static_cast<std::size_t>(kLocalCvNeighbours));
    double sum = 0.0;
    for (const Eigen::Index i : near) sum += known_squared_m2(i);
    return std::sqrt(sum / static_cast<double>(near.size()));
  }
};

Corrector::Corrector(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

std::optional<Corrector> Corrector::try_fit(const CorrectorData& data,
                                            const CorrectorOptions& options, std::string& why) {
  options.validate();
  data.validate();
  auto impl = std::make_shared<Impl>();
  impl->T_robot_sensor = data.T_robot_sensor;
  impl->requested = options.interpolation;
  impl->nearest_configuration = options.nearest_configuration;
  impl->cv_folds = options.cv_folds;
  impl->cv_seed = options.cv_seed;
  const MethodSettings settings =
      method_settings(options.interpolation, options.nearest_configuration);
  const InterpolationMethod method = options.interpolation.method;
  const ProgressStage progress("fitting " + std::string(to_string(method)) + " to " +
                                   std::to_string(data.size()) + " fiducials",
                               1);
  // The method's cross-validation (auto's table, or the sd of a model without one of its own).
  const auto cross_validated = [&](const CrossValidationRow& row) {
    impl->cv_rms_m = row.rms_m;
    impl->sd_source = cv_sd_source(row.method);
    if (impl->sd_source == SdSource::kLocalCv) impl->cv_squared_error_m2 = row.squared_error_m2;
  };
  if (method == InterpolationMethod::kAuto) {
    FitOutcome chosen;
    impl->cross_validation = choose_by_cross_validation(data, settings, options.cv_folds,
                                                        options.cv_seed, &chosen);
    impl->fitted = std::move(chosen.fitted);
    for (const CrossValidationRow& row : impl->cross_validation->rows) {
      if (row.method == impl->cross_validation->chosen) cross_validated(row);
    }
    if (impl->fitted->has_own_sd()) {
      impl->sd_source = SdSource::kModel;
      impl->cv_squared_error_m2.resize(0);
    }
  } else if (method == InterpolationMethod::kLinear || method == InterpolationMethod::kGrid) {
    // Linear weights: trilinear on a complete regular grid, else barycentric (Eq. 7).
    FitOutcome grid = fit_method(InterpolationMethod::kGrid, data, settings);
    if (!grid.fitted && method == InterpolationMethod::kGrid) {
      why = "grid interpolation needs fiducials on a complete regular grid: " + grid.not_applicable;
      return std::nullopt;
    }
    if (!grid.fitted) grid = fit_method(InterpolationMethod::kScattered, data, settings);
    if (!grid.fitted) {
      why = grid.not_applicable;
      return std::nullopt;
    }
    impl->fitted = std::move(grid.fitted);
  } else if (method == InterpolationMethod::kKriging) {  // its own posterior sd: no CV needed
    FitOutcome kriging = fit_method(method, data, settings);
    if (!kriging.fitted) {
      why = "kriging interpolation cannot be used: " + kriging.not_applicable;
      return std::nullopt;
    }
    impl->fitted = std::move(kriging.fitted);
    impl->sd_source = SdSource::kModel;
  } else if (correction_method(method).field_model) {
    // The model's own uncertainty is its cross-validated error.
    const std::vector<Eigen::Index> units = fold_units(data.fiducials_robot_m);
    FitOutcome full;
    const CrossValidationRow row =
        cross_validate(method, data, settings, assign_folds(units, options.cv_folds, options.cv_seed),
                       units, options.cv_folds, &full);
    if (!row.applicable || !full.fitted) {
      why = std::string(to_string(method)) + " interpolation cannot be used on these fiducials: " +
            row.note;
      return std::nullopt;
    }
    impl->fitted = std::move(full.fitted);
    cross_validated(row);
  } else {
    FitOutcome stencils = fit_method(method, data, settings);
    if (!stencils.fitted) {
      why = stencils.not_applicable;
      return std::nullopt;
    }
    impl->fitted = std::move(stencils.fitted);
  }
  impl->index_known(data);
  impl->field_scales(data);
  const InterpolationMethod fitted = impl->fitted->method();
  if (options.tabulate && data.size() <= kLargeCellFiducials &&
      (fitted == InterpolationMethod::kKriging || fitted == InterpolationMethod::kRbf)) {
    const Impl& m = *impl;
    const detail::ExactField exact = [&m](const Points3& at, Points3& c, Eigen::VectorXd& s) {
      m.exact_predictions(at, c, s);
    };
    std::optional<detail::FieldTable> table =
        detail::build_field_table(exact, data.fiducials_robot_m, data.noise_sd_m);
    if (table) {
      impl->fitted = detail::tabulated_method(std::move(*table), fitted, impl->fitted->save(),
                                              impl->fitted->describe());
      impl->tabulated = true;
    }
  }
  return Corrector(std::move(impl));
}

Corrector Corrector::fit(const CorrectorData& data, const CorrectorOptions& options) {
  std::string why;
  std::optional<Corrector> out = try_fit(data, options, why);
  VRREG_THROW_UNLESS(out, why);
  return std::move(*out);
}


Corrector Corrector::restore(const SavedCorrector& saved, const CorrectorData& data) {
  data.validate();
  saved.requested.validate();
  auto impl = std::make_shared<Impl>();
  impl->T_robot_sensor = data.T_robot_sensor;
  impl->requested = saved.requested;
  impl->nearest_configuration = saved.nearest_configuration;
  impl->cv_folds = saved.cv_folds;
  impl->cv_seed = saved.cv_seed;
  impl->cross_validation = saved.cross_validation;
  impl->sd_source = saved.sd_source;
  impl->cv_rms_m = saved.cv_rms_m;
  impl->cv_squared_error_m2 = saved.cv_squared_error_m2;
  if (detail::is_tabulated(saved.state)) {
    impl->fitted = detail::restore_tabulated(saved.state, saved.method);
    impl->tabulated = true;
  } else {
    impl->fitted = correction_method(saved.method)
                       .restore(saved.state, data,
                                method_settings(saved.requested, saved.nearest_configuration));
  }
  VRREG_THROW_UNLESS(impl->fitted->method() == saved.method,
                     "the saved corrector is " << to_string(saved.method) << ", restored as "
                                               << to_string(impl->fitted->method()));
  impl->index_known(data);
  impl->field_scales(data);
  return Corrector(std::move(impl));
}

Corrector Corrector::exact(const CorrectorData& data) const {
  if (!impl_->tabulated) return *this;
  SavedCorrector saved = save();
  saved.state = detail::exact_state_of(saved.state);
  return restore(saved, data);
}

bool Corrector::tabulated() const { return impl_->tabulated; }

SavedCorrector Corrector::save() const {
  SavedCorrector out;
  out.requested = impl_->requested;
  out.nearest_configuration = impl_->nearest_configuration;
  out.cv_folds = impl_->cv_folds;
  out.cv_seed = impl_->cv_seed;
  out.method = impl_->fitted->method();
  out.state = impl_->fitted->save();
  out.cross_validation = impl_->cross_validation;
  out.sd_source = impl_->sd_source;
  out.cv_rms_m = impl_->cv_rms_m;
  out.cv_squared_error_m2 = impl_->cv_squared_error_m2;
  return out;
}

TargetCorrection Corrector::correct(const CorrectionQuery& query) const {
  const Impl& m = *impl_;
  const FittedMethod& method = *m.fitted;
  const Eigen::Index n = query.sensor_m.cols();
  VRREG_THROW_UNLESS(query.sensor_m.allFinite(),
                     "the targets' sensor coordinates are not all finite");
  const MethodNeeds needs = method.needs();
  VRREG_THROW_UNLESS(!needs.nominal_robot || query.robot_nominal_m.cols() == n,
                     to_string(method.method())
                         << " interpolation needs the targets' nominal robot positions");
  VRREG_THROW_UNLESS(query.robot_nominal_m.cols() == 0 || query.robot_nominal_m.cols() == n,
                     "got " << query.robot_nominal_m.cols() << " nominal robot positions for "
                            << n << " targets");
  VRREG_THROW_UNLESS(query.robot_nominal_m.allFinite(),
                     "the targets' nominal robot coordinates are not all finite");
  VRREG_THROW_UNLESS(!needs.joints || query.joints_rad.cols() == n,
                     to_string(method.method()) << " interpolation needs every target's joint angles");
  VRREG_THROW_UNLESS(query.joints_rad.allFinite(), "the targets' joint angles are not all finite");
  VRREG_THROW_UNLESS(query.sequence.empty() || query.sequence.size() == static_cast<std::size_t>(n),
                     "got " << query.sequence.size() << " sequence numbers for " << n
                            << " targets");

  TargetCorrection out;
  out.method_used = method.method();
  out.layout = method.describe();
  MethodPredictions p;
  detail::allocate_stencils(p.stencils, n);
  detail::allocate_points(p.corrections_sensor_m, n);
  detail::allocate_points(out.corrected_sensor_m, n);
  detail::allocate_points(out.corrected_robot_m, n);
  detail::allocate_points(out.uncorrected_robot_m, n);
  if (method.has_own_sd()) p.sd_m.resize(n);
  const bool with_sd = m.sd_source != SdSource::kNone;
  if (with_sd) out.predicted_sd_m.resize(n);
  const SimilarityTransform& T = m.T_robot_sensor;
  const MethodQuery method_query{out.uncorrected_robot_m, query.robot_nominal_m, query.joints_rad,
                                 query.sequence};
  const Eigen::Index block = std::max<Eigen::Index>(method.block_size(), 1);
  const Eigen::Index n_blocks = (n + block - 1) / block;
  std::atomic<int> n_flagged{0};
  ProgressStage progress("correcting " + std::to_string(n) + " points", n_blocks);
  const auto register_blocks = [&](Eigen::Index b0, Eigen::Index b1) {
    for (Eigen::Index i = b0 * block; i < std::min(n, b1 * block); ++i)
      out.uncorrected_robot_m.col(i) = T.apply(Eigen::Vector3d(query.sensor_m.col(i)));
  };
  const auto correct_blocks = [&](Eigen::Index b0, Eigen::Index b1) {
    int flagged = 0;
    for (Eigen::Index b = b0; b < b1; ++b) {
      const Eigen::Index begin = b * block;
      const Eigen::Index end = std::min(n, begin + block);
      method.predict(method_query, begin, end, p);
      for (Eigen::Index i = begin; i < end; ++i) {
        if (p.stencils[static_cast<std::size_t>(i)].status != StencilStatus::kOk) {
          ++flagged;
          p.corrections_sensor_m.col(i).setZero();
          out.corrected_sensor_m.col(i) = query.sensor_m.col(i);
          out.corrected_robot_m.col(i) = out.uncorrected_robot_m.col(i);
          if (with_sd) out.predicted_sd_m(i) = std::numeric_limits<double>::quiet_NaN();
          continue;
        }
        const Eigen::Vector3d corrected = query.sensor_m.col(i) + p.corrections_sensor_m.col(i);
        out.corrected_sensor_m.col(i) = corrected;  // Eq. 8
        out.corrected_robot_m.col(i) = T.apply(corrected);
        // The error of a corrected target is the field's error plus the target's own noise; the
        // cross-validated errors hold both (a held-out fiducial is noisy too), kriging gives
        // them apart.
        if (!with_sd) continue;
        out.predicted_sd_m(i) = method.has_own_sd()               ? p.sd_m(i)
                                : m.sd_source == SdSource::kLocalCv ? m.local_sd_m(out.uncorrected_robot_m.col(i))
                                                                    : m.cv_rms_m;
      }
      progress.advance();
    }
    n_flagged.fetch_add(flagged, std::memory_order_relaxed);
  };
  if (n < kSerialBelow || n_blocks < 2) {
    register_blocks(0, n_blocks);
    method.check_query(method_query);
    correct_blocks(0, n_blocks);
  } else {
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, n_blocks),
                      [&](const tbb::blocked_range<Eigen::Index>& r) {
                        register_blocks(r.begin(), r.end());
                      });
    method.check_query(method_query);
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, n_blocks),
                      [&](const tbb::blocked_range<Eigen::Index>& r) {
                        correct_blocks(r.begin(), r.end());
                      });
  }
  out.stencils = std::move(p.stencils);
  out.corrections_sensor_m = std::move(p.corrections_sensor_m);
  out.n_flagged = n_flagged.load();
  if (query.extrapolate && out.n_flagged > 0) m.extrapolate(query, out);
  return out;
}

InterpolationMethod Corrector::method() const { return impl_->fitted->method(); }
const InterpolationSettings& Corrector::requested() const { return impl_->requested; }
std::string Corrector::describe() const { return impl_->fitted->describe(); }
MethodNeeds Corrector::needs() const { return impl_->fitted->needs(); }
const std::optional<kinematics::JointNorm>& Corrector::nearest_configuration() const {
  return impl_->nearest_configuration;
}
SdSource Corrector::sd_source() const { return impl_->sd_source; }
const std::optional<CrossValidation>& Corrector::cross_validation() const {
  return impl_->cross_validation;
}
std::optional<Eigen::VectorXd> Corrector::joint_angle_errors_rad(
    const Eigen::Ref<const Eigen::VectorXd>& joints_rad) const {
  return impl_->fitted->joint_angle_errors_rad(joints_rad);
}

std::optional<Eigen::Vector3d> Corrector::rotation_error_rad(
    const Eigen::Ref<const Eigen::VectorXd>& joints_rad, bool joint_angles_only) const {
  return impl_->fitted->rotation_error_rad(joints_rad, joint_angles_only);
}

const SimilarityTransform& Corrector::T_robot_sensor() const { return impl_->T_robot_sensor; }

}  // namespace vrreg
