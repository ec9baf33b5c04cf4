// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/corrector.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "buffers.hpp"
#include "far_field.hpp"
#include "lost_motion_stage.hpp"
#include "method_support.hpp"
#include "method_tabulated.hpp"
#include "point_index.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/progress.hpp"

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

// The guard of a corrector fitted with `fitted`: from its own cross-validation when it has one
// (auto's chosen row, a field model's, trilinear's and scattered's), else from trilinear's (the
// paper's stencils: a complete grid or an octuplet's cubes lose their corners when a fold is
// held out; trilinear interpolates with the same weights between the same nodes). Scattered
// does not stand in: on a small lattice it predicts only the few interior fiducials, with a
// Delaunay mesh much worse than the stencil it would judge (the 27-fiducial cube held the
// octuplet back where it halves the error).
// `given`: the fiducials as measured, against whose corrections the guard judges; `data`: what the
// method fitted (without the lost-motion term when it entered, so its held-out errors are the
// whole correction's).
CorrectionGuard guard_of(const CorrectorData& given, const CorrectorData& data,
                         const MethodSettings& settings, const CorrectorOptions& options,
                         const std::optional<CrossValidationRow>& judged,
                         InterpolationMethod fitted) {
  const std::vector<Eigen::Index> units = fold_units(data.fiducials_robot_m);
  if (judged) return judge_correction(*judged, given, units);
  const std::vector<int> fold_of = assign_folds(units, options.cv_folds, options.cv_seed);
  const bool own = fitted == InterpolationMethod::kTrilinear ||
                   fitted == InterpolationMethod::kScattered;
  const InterpolationMethod judge = own ? fitted : InterpolationMethod::kTrilinear;
  return judge_correction(cross_validate(judge, data, settings, fold_of, units, options.cv_folds),
                          given, units);
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
      sequence(sequence_),
      approach_sign(no_joints()) {}

CorrectionQuery::CorrectionQuery(const ConstPoints3Ref& sensor_m_,
                                 const ConstPoints3Ref& robot_nominal_m_,
                                 const Eigen::Ref<const Eigen::MatrixXd>& joints_rad_,
                                 std::span<const std::size_t> sequence_,
                                 const Eigen::Ref<const Eigen::MatrixXd>& approach_sign_)
    : sensor_m(sensor_m_),
      robot_nominal_m(robot_nominal_m_),
      joints_rad(joints_rad_),
      sequence(sequence_),
      approach_sign(approach_sign_) {}

struct Corrector::Impl {
  std::unique_ptr<const FittedMethod> fitted;
  SimilarityTransform T_robot_sensor;
  InterpolationSettings requested;
  std::optional<kinematics::JointNorm> nearest_configuration;
  int cv_folds = 5;
  std::uint64_t cv_seed = 1;
  bool tabulated = false;
  std::optional<CrossValidation> cross_validation;
  std::optional<CorrectionGuard> guard;
  std::optional<LostMotionTerm> lost_motion;
  std::optional<kinematics::SerialChain> robot;  ///< the term's arm, when the term is applied
  SdSource sd_source = SdSource::kNone;
  double cv_rms_m = 0.0;
  Eigen::VectorXd cv_squared_error_m2;  ///< per fiducial, NaN where not predicted (kLocalCv)
  /// kLocalCv: the fiducials with a held-out error, indexed, and their errors in that order.
  std::optional<detail::PointIndex> known_index;
  /// What extrapolation (CorrectionQuery::extrapolate) knows of the field (far_field.hpp).
  std::optional<detail::FarField> far;
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

  /// The sd the corrector gives a correction the method made at registered `at_m`: the
  /// method's own, its local or global cross-validation, or none (NaN).
  [[nodiscard]] double method_sd_m(const MethodPredictions& p, Eigen::Index j,
                                   const Eigen::Vector3d& at_m) const {
    return fitted->has_own_sd()                ? p.sd_m(j)
           : sd_source == SdSource::kLocalCv   ? local_sd_m(at_m)
           : sd_source == SdSource::kGlobalCv  ? cv_rms_m
                                               : std::numeric_limits<double>::quiet_NaN();
  }

  /// Whether a point the method flagged `status` at registered `at_m` lies beyond its support
  /// (so is extrapolated on request): outside the support, grid or hull, or an octuplet's
  /// missing corner outside the fiducials' box; a hole inside the layout is not.
  [[nodiscard]] bool beyond_support(StencilStatus status, const Eigen::Vector3d& at_m) const {
    switch (status) {
      case StencilStatus::kOutsideSupport:
      case StencilStatus::kOutsideGrid:
      case StencilStatus::kOutsideHull:
        return true;
      case StencilStatus::kMissingCorner:
        return (at_m.array() < far->box_lo_m().array()).any() ||
               (at_m.array() > far->box_hi_m().array()).any();
      default:
        return false;
    }
  }

  /// Corrects the points of `out` beyond the support (CorrectionQuery::extrapolate), every
  /// method alike (far_field.hpp): with the correction at the support's nearest point (the
  /// method's own clamp, else the fiducials' box), the method's where it answers there, else the
  /// mean of the fiducials nearest it; its sd widened for what lies between.
  void extrapolate(const CorrectionQuery& query, TargetCorrection& out) const {
    std::vector<Eigen::Index> outside;
    for (std::size_t i = 0; i < out.stencils.size(); ++i) {
      const auto ii = static_cast<Eigen::Index>(i);
      if (beyond_support(out.stencils[i].status, out.uncorrected_robot_m.col(ii)))
        outside.push_back(ii);
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
    Points3 anchor_m = at_m;
    std::optional<Eigen::VectorXd> moved_m = fitted->clamp_to_support(anchor_m, q_rad);
    if (!moved_m) moved_m = detail::SupportBox::clamp_to_box(anchor_m, far->box_lo_m(), far->box_hi_m());
    // The method at the anchors, unless it reads the points' nominal positions (the octuplet):
    // an anchor has none.
    MethodPredictions p;
    p.corrections_sensor_m.setZero(3, k);
    p.stencils.assign(static_cast<std::size_t>(k), detail::flagged_stencil(StencilStatus::kOutsideSupport));
    if (fitted->has_own_sd()) p.sd_m.resize(k);
    if (fitted->judges_gaps()) p.gap_sd_m.setZero(k);
    if (!fitted->needs().nominal_robot) {
      const Points3 none(3, 0);
      const MethodQuery edge{anchor_m, none, q_rad, {}};
      const Eigen::Index block = std::max<Eigen::Index>(fitted->block_size(), 1);
      for (Eigen::Index begin = 0; begin < k; begin += block)
        fitted->predict(edge, begin, std::min(k, begin + block), p);
    }
    if (out.predicted_sd_m.size() == 0)
      out.predicted_sd_m = Eigen::VectorXd::Constant(query.sensor_m.cols(), std::numeric_limits<double>::quiet_NaN());
    for (Eigen::Index j = 0; j < k; ++j) {
      const Eigen::Index i = outside[static_cast<std::size_t>(j)];
      const Eigen::Vector3d anchor = anchor_m.col(j);
      Eigen::Vector3d anchor_correction_m;
      double sd_anchor_m = 0.0;
      far->nearest_mean(anchor, anchor_correction_m, sd_anchor_m);
      // A joint clamped into its range leaves the model a combination of joints no fiducial had:
      // its value there is no guide (the joint model of a 60 mm cube, 60 mm beyond it: 10.9 mm
      // off where the uncorrected mapping was 0.78 mm off).
      if (std::isfinite((*moved_m)(j)) &&
          p.stencils[static_cast<std::size_t>(j)].status == StencilStatus::kOk) {
        anchor_correction_m = p.corrections_sensor_m.col(j);
        const double own_sd_m = method_sd_m(p, j, anchor);
        if (std::isfinite(own_sd_m)) sd_anchor_m = own_sd_m;
        if (p.gap_sd_m.size() > 0) sd_anchor_m = std::hypot(sd_anchor_m, p.gap_sd_m(j));
      }
      const Eigen::Vector3d at = at_m.col(j);
      anchor_correction_m += far->trend_step_sensor_m(at, anchor);
      out.stencils[static_cast<std::size_t>(i)] = Stencil{};
      out.stencils[static_cast<std::size_t>(i)].status = StencilStatus::kExtrapolated;
      out.corrections_sensor_m.col(i) = anchor_correction_m;
      out.corrected_sensor_m.col(i) = query.sensor_m.col(i) + anchor_correction_m;
      out.corrected_robot_m.col(i) = T_robot_sensor.apply(Eigen::Vector3d(out.corrected_sensor_m.col(i)));
      const bool clamped = !std::isfinite((*moved_m)(j));  // a joint moved: no length
      out.predicted_sd_m(i) =
          far->extrapolated_sd_m(sd_anchor_m, (*moved_m)(j), at, anchor, clamped);
      --out.n_flagged;
    }
  }

  /// Adds the applied lost-motion term to the points the method corrected (or extrapolated), at
  /// their joints and approach directions, and its variance to their sd.
  void add_lost_motion(const CorrectionQuery& query, TargetCorrection& out) const {
    std::vector<Eigen::Index> corrected;
    for (std::size_t i = 0; i < out.stencils.size(); ++i) {
      const StencilStatus status = out.stencils[i].status;
      if (status == StencilStatus::kOk || status == StencilStatus::kExtrapolated)
        corrected.push_back(static_cast<Eigen::Index>(i));
    }
    const auto k = static_cast<Eigen::Index>(corrected.size());
    const bool known = query.approach_sign.size() > 0;
    Eigen::MatrixXd q_rad(query.joints_rad.rows(), k);
    Eigen::MatrixXd sign(known ? query.approach_sign.rows() : 0, known ? k : 0);
    for (Eigen::Index j = 0; j < k; ++j) {
      q_rad.col(j) = query.joints_rad.col(corrected[static_cast<std::size_t>(j)]);
      if (known) sign.col(j) = query.approach_sign.col(corrected[static_cast<std::size_t>(j)]);
    }
    const detail::LostMotionPrediction term =
        detail::predict_lost_motion(*robot, T_robot_sensor, *lost_motion, q_rad, sign);
    for (Eigen::Index j = 0; j < k; ++j) {
      const Eigen::Index i = corrected[static_cast<std::size_t>(j)];
      out.corrections_sensor_m.col(i) += term.corrections_sensor_m.col(j);
      out.corrected_sensor_m.col(i) = query.sensor_m.col(i) + out.corrections_sensor_m.col(i);
      out.corrected_robot_m.col(i) =
          T_robot_sensor.apply(Eigen::Vector3d(out.corrected_sensor_m.col(i)));
      if (out.predicted_sd_m.size() > 0)
        out.predicted_sd_m(i) = std::sqrt(out.predicted_sd_m(i) * out.predicted_sd_m(i) +
                                          term.variance_m2(j));
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

std::optional<Corrector> Corrector::try_fit(const CorrectorData& given,
                                            const CorrectorOptions& options, std::string& why) {
  options.validate();
  given.validate();
  auto impl = std::make_shared<Impl>();
  // The lost-motion stage first: when it enters, the method fits what the term leaves.
  std::optional<CorrectorData> staged;
  if (options.lost_motion != LostMotionMode::kOff) {
    const std::string unavailable = detail::lost_motion_unavailable(given);
    VRREG_THROW_UNLESS(unavailable.empty() || options.lost_motion != LostMotionMode::kOn,
                       "lost motion cannot be fitted: " << unavailable);
    // A large cell's (a scanner's) plays would be a least-squares problem of 3N x 36 numbers:
    // auto leaves the term to be asked for.
    const bool large =
        given.size() > kLargeCellFiducials && options.lost_motion == LostMotionMode::kAuto;
    if (unavailable.empty() && !large) {
      const MethodSettings judge_settings =
          method_settings(options.interpolation, options.nearest_configuration);
      try {
        impl->lost_motion = detail::fit_lost_motion_term(
            given, options.lost_motion, judge_settings, options.cv_folds, options.cv_seed,
            options.interpolation.method);
      } catch (const InputError&) {
        // Too few fiducials for the plays and the trend: auto goes on without the term.
        if (options.lost_motion == LostMotionMode::kOn) throw;
      }
      if (impl->lost_motion && impl->lost_motion->applied) {
        staged = detail::without_lost_motion(given, impl->lost_motion->play_rad);
        impl->robot = given.robot;
      }
    }
  }
  const CorrectorData& data = staged ? *staged : given;
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
  std::optional<CrossValidationRow> judged;  // the guard's cross-validation, when it has one
  if (method == InterpolationMethod::kAuto) {
    FitOutcome chosen;
    impl->cross_validation = choose_by_cross_validation(data, settings, options.cv_folds,
                                                        options.cv_seed, &chosen);
    impl->fitted = std::move(chosen.fitted);
    for (const CrossValidationRow& row : impl->cross_validation->rows) {
      if (row.method == impl->cross_validation->chosen) {
        cross_validated(row);
        judged = row;
      }
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
  } else if (method == InterpolationMethod::kKriging) {  // its own posterior sd; CV for the guard
    FitOutcome kriging;
    if (options.guard) {
      const std::vector<Eigen::Index> units = fold_units(data.fiducials_robot_m);
      judged = cross_validate(method, data, settings,
                              assign_folds(units, options.cv_folds, options.cv_seed), units,
                              options.cv_folds, &kriging);
      if (!kriging.fitted) kriging = fit_method(method, data, settings);  // folds too few
    } else {
      kriging = fit_method(method, data, settings);
    }
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
    judged = row;
  } else {
    FitOutcome stencils = fit_method(method, data, settings);
    if (!stencils.fitted) {
      why = stencils.not_applicable;
      return std::nullopt;
    }
    impl->fitted = std::move(stencils.fitted);
  }
  if (options.guard)
    impl->guard = guard_of(given, data, settings, options, judged, impl->fitted->method());
  impl->index_known(data);
  impl->far.emplace(data);
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
                                              impl->fitted->describe(), data.values);
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


Corrector Corrector::restore(const SavedCorrector& saved, const CorrectorData& given) {
  given.validate();
  saved.requested.validate();
  auto impl = std::make_shared<Impl>();
  impl->lost_motion = saved.lost_motion;
  std::optional<CorrectorData> staged;
  if (saved.lost_motion && saved.lost_motion->applied) {
    const std::string unavailable = detail::lost_motion_unavailable(given);
    VRREG_THROW_UNLESS(unavailable.empty(),
                       "the saved corrector corrects lost motion, but " << unavailable);
    VRREG_THROW_UNLESS(saved.lost_motion->play_rad.size() == given.joints_rad.rows() &&
                           saved.lost_motion->covariance_rad2.rows() == given.joints_rad.rows() &&
                           saved.lost_motion->covariance_rad2.cols() == given.joints_rad.rows(),
                       "the saved lost-motion term has " << saved.lost_motion->play_rad.size()
                                                         << " plays for "
                                                         << given.joints_rad.rows() << " joints");
    staged = detail::without_lost_motion(given, saved.lost_motion->play_rad);
    impl->robot = given.robot;
  }
  const CorrectorData& data = staged ? *staged : given;
  impl->T_robot_sensor = data.T_robot_sensor;
  impl->requested = saved.requested;
  impl->nearest_configuration = saved.nearest_configuration;
  impl->cv_folds = saved.cv_folds;
  impl->cv_seed = saved.cv_seed;
  impl->cross_validation = saved.cross_validation;
  impl->guard = saved.guard;
  impl->sd_source = saved.sd_source;
  impl->cv_rms_m = saved.cv_rms_m;
  impl->cv_squared_error_m2 = saved.cv_squared_error_m2;
  if (detail::is_tabulated(saved.state)) {
    impl->fitted = detail::restore_tabulated(saved.state, saved.method, data.values);
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
  impl->far.emplace(data);
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
  out.guard = impl_->guard;
  out.sd_source = impl_->sd_source;
  out.cv_rms_m = impl_->cv_rms_m;
  out.cv_squared_error_m2 = impl_->cv_squared_error_m2;
  out.lost_motion = impl_->lost_motion;
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

  const bool with_lost_motion =
      m.lost_motion && m.lost_motion->applied && (!m.guard || m.guard->applied);
  VRREG_THROW_UNLESS(!with_lost_motion || query.joints_rad.cols() == n,
                     "the model corrects lost motion: give the joints (and from_q or the visiting "
                     "order) of every point");

  TargetCorrection out;
  out.method_used = method.method();
  out.layout = method.describe();
  out.guard = m.guard;
  MethodPredictions p;
  detail::allocate_stencils(p.stencils, n);
  detail::allocate_points(p.corrections_sensor_m, n);
  detail::allocate_points(out.corrected_sensor_m, n);
  detail::allocate_points(out.corrected_robot_m, n);
  detail::allocate_points(out.uncorrected_robot_m, n);
  if (method.has_own_sd()) p.sd_m.resize(n);
  if (method.judges_gaps()) p.gap_sd_m.setZero(n);
  const bool with_sd = m.sd_source != SdSource::kNone;
  if (with_sd) out.predicted_sd_m.resize(n);
  const SimilarityTransform& T = m.T_robot_sensor;
  const MethodQuery method_query{out.uncorrected_robot_m, query.robot_nominal_m, query.joints_rad,
                                 query.sequence};
  const Eigen::Index block = std::max<Eigen::Index>(method.block_size(), 1);
  const Eigen::Index n_blocks = (n + block - 1) / block;
  std::atomic<int> n_flagged{0};
  const bool applied = !m.guard || m.guard->applied;
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
        StencilStatus& status = p.stencils[static_cast<std::size_t>(i)].status;
        if (!applied && status == StencilStatus::kOk) status = StencilStatus::kNotBetterThanNone;
        if (status != StencilStatus::kOk) {
          ++flagged;
          p.corrections_sensor_m.col(i).setZero();
          out.corrected_sensor_m.col(i) = query.sensor_m.col(i);
          out.corrected_robot_m.col(i) = out.uncorrected_robot_m.col(i);
          // An unapplied correction's target is off by what an uncorrected fiducial is.
          if (with_sd) {
            out.predicted_sd_m(i) = status == StencilStatus::kNotBetterThanNone
                                        ? m.guard->uncorrected_rms_m
                                        : std::numeric_limits<double>::quiet_NaN();
          }
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
        if (p.gap_sd_m.size() > 0) out.predicted_sd_m(i) = std::hypot(out.predicted_sd_m(i), p.gap_sd_m(i));
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
  if (query.extrapolate && applied && out.n_flagged > 0) m.extrapolate(query, out);
  if (with_lost_motion) m.add_lost_motion(query, out);
  return out;
}

InterpolationMethod Corrector::method() const { return impl_->fitted->method(); }
const InterpolationSettings& Corrector::requested() const { return impl_->requested; }
std::string Corrector::describe() const { return impl_->fitted->describe(); }
MethodNeeds Corrector::needs() const {
  MethodNeeds needs = impl_->fitted->needs();
  // The lost-motion term is evaluated at the commanded joints.
  if (impl_->lost_motion && impl_->lost_motion->applied) needs.joints = true;
  return needs;
}
const std::optional<kinematics::JointNorm>& Corrector::nearest_configuration() const {
  return impl_->nearest_configuration;
}
SdSource Corrector::sd_source() const { return impl_->sd_source; }
const std::optional<CrossValidation>& Corrector::cross_validation() const {
  return impl_->cross_validation;
}
const std::optional<CorrectionGuard>& Corrector::guard() const { return impl_->guard; }
const std::optional<LostMotionTerm>& Corrector::lost_motion() const {
  return impl_->lost_motion;
}
bool Corrector::applied() const { return !impl_->guard || impl_->guard->applied; }
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
