// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/evaluate.hpp"

#include <vector>

#include "procedure2_steps.hpp"
#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/metrics/errors.hpp"

namespace vrreg {
namespace {

using planning::Strategy;

// The strategy evaluate follows: the model's, or 1 on a model built without one.
Strategy strategy_to_use(const RegistrationModel& model, const EvaluateOptions& options) {
  const Strategy built = model.procedure2.strategy;
  const Strategy s = options.strategy.value_or(built);
  VRREG_THROW_UNLESS(s == built || (s == Strategy::kAsListed && built == Strategy::kNone),
                     "the model was built with "
                         << (built == Strategy::kNone
                                 ? std::string("no strategy")
                                 : "`strategy` " + std::to_string(planning::strategy_number(built)))
                         << ", not `strategy` " << planning::strategy_number(s)
                         << ": register again with it");
  VRREG_THROW_UNLESS(
      !options.joint_norm || s == Strategy::kAlongPath || s == Strategy::kVolumeCorners,
      "`joint_norm` is for strategies 2 and 3");
  VRREG_THROW_UNLESS(s != Strategy::kAlongPath || !options.joint_norm ||
                         *options.joint_norm == model.procedure2.joint_norm,
                     "the model's Strategy 2 labels use `joint_norm` "
                         << kinematics::to_string(model.procedure2.joint_norm)
                         << "; the targets must use the same");
  return s;
}

// The angle errors of the corrected orientations against the commanded ones.
std::optional<OrientationEvaluation> orientation_errors(std::optional<OrientationCorrection> c,
                                                        const MeasurementSet& set,
                                                        const std::vector<std::size_t>& rows) {
  if (!c) return std::nullopt;
  for (const std::size_t r : rows) {
    if (!set.locations[r].q_robot_marker) return std::nullopt;  // nothing to compare with
  }
  OrientationEvaluation out;
  const auto n = static_cast<Eigen::Index>(rows.size());
  out.unc_error_rad.resize(n);
  out.cor_error_rad.resize(n);
  std::vector<Eigen::Index> corrected;
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const Eigen::Matrix3d R_commanded = set.locations[rows[i]].q_robot_marker->toRotationMatrix();
    out.unc_error_rad(k) = rotation_angle_rad(c->uncorrected_R_robot_marker[i], R_commanded);
    out.cor_error_rad(k) = rotation_angle_rad(c->corrected_R_robot_marker[i], R_commanded);
    // A field not better than none answers every target uncorrected: those count as answered.
    if (is_corrected(c->status[i]) || c->status[i] == StencilStatus::kNotBetterThanNone) {
      corrected.push_back(k);
    }
  }
  if (!corrected.empty()) {
    out.unc_rms_rad = root_mean_square(out.unc_error_rad(corrected));
    out.cor_rms_rad = root_mean_square(out.cor_error_rad(corrected));
  }
  out.calibration = uncertainty_calibration(out.cor_error_rad, c->predicted_sd_rad);
  out.correction = std::move(*c);
  return out;
}

// ISO 9283's multi-directional accuracy over the corrected targets, from each row's approach
// directions; none when no target point was visited from two directions.
std::optional<MultidirectionalAccuracy> multidirectional_of(const EvaluateResult& r,
                                                            const MeasurementSet& set,
                                                            const std::vector<std::size_t>& rows) {
  std::vector<std::vector<double>> signs;
  std::vector<bool> corrected;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    signs.push_back(set.locations[rows[i]].approach_sign);
    corrected.push_back(is_corrected(r.correction.stencils[i].status));
  }
  MultidirectionalAccuracy m = multidirectional_accuracy(
      r.targets_robot_m, r.correction.uncorrected_robot_m, r.correction.corrected_robot_m, signs,
      r.names,
      r.configs.size() == rows.size() ? r.configs : std::vector<std::optional<int>>{}, corrected);
  if (m.n_points == 0) return std::nullopt;
  return m;
}

EvaluateResult evaluate_set(const RegistrationModel& model, const MeasurementSet& file_set,
                            const EvaluateOptions& options) {
  model.validate();
  EvaluateResult out;
  out.strategy = strategy_to_use(model, options);
  const kinematics::JointNorm norm = options.joint_norm.value_or(model.procedure2.joint_norm);
  // A model built for one configuration is evaluated on that configuration unless told otherwise.
  out.config = options.config ? options.config : model.config;
  VRREG_THROW_UNLESS(out.strategy != Strategy::kAsListed || out.config,
                     "`strategy` 1 evaluates one configuration: give `config`");
  pipeline_detail::PointsToCorrect points;
  pipeline_detail::prepare_points(model, file_set, out.strategy, norm, out.config, true, points);
  const MeasurementSet* set = points.set;
  const std::vector<std::size_t>& rows = points.rows;
  out.relabelled = points.relabelled;
  out.targets_robot_m = set->robot_points(rows);
  out.interpolation = options.interpolation.apply(model.interpolation);
  const pipeline_detail::CorrectorRequest request{out.interpolation, out.strategy, norm,
                                                  options.robot, options.refit,
                                                  options.exact, options.extrapolate};
  std::optional<OrientationCorrection> orientation;
  out.correction = pipeline_detail::correct_rows(model, *set, rows, request, out.targets_robot_m,
                                                 &out.cross_validation, &orientation);
  out.orientation = orientation_errors(std::move(orientation), *set, rows);
  // Flagged targets keep their uncorrected mapping: that is what `correct` would hand the robot.
  out.unc_tre_m = point_errors(out.correction.uncorrected_robot_m, out.targets_robot_m);  // Eq. 3
  out.cor_tre_m = point_errors(out.correction.corrected_robot_m, out.targets_robot_m);
  // The summary never mixes corrected and uncorrected targets: RMS_T, gamma and N_bad are over
  // the corrected ones, and the others are counted apart with their own RMS_T.
  std::vector<Eigen::Index> corrected, flagged;
  for (Eigen::Index k = 0; k < out.unc_tre_m.size(); ++k) {
    const bool ok = is_corrected(out.correction.stencils[static_cast<std::size_t>(k)].status);
    (ok ? corrected : flagged).push_back(k);
  }
  out.flagged_rms_t_m = flagged.empty() ? 0.0 : root_mean_square(out.unc_tre_m(flagged));  // Eq. 4
  out.summary = summarize_improvement(out.unc_tre_m(corrected), out.cor_tre_m(corrected));
  for (int& k : out.summary.bad_targets)
    k = static_cast<int>(corrected[static_cast<std::size_t>(k)]);
  out.calibration =
      uncertainty_calibration(out.cor_tre_m, out.correction.predicted_sd_m);
  pipeline_detail::labels_of(*set, rows, out.names, out.configs);
  for (const int n : out.summary.bad_targets)
    out.bad_targets.push_back(out.names[static_cast<std::size_t>(n)]);
  out.multidirectional = multidirectional_of(out, *set, rows);
  return out;
}

}  // namespace

EvaluateResult evaluate(const RegistrationModel& model, const MeasurementSet& targets,
                        const EvaluateOptions& options) {
  return evaluate_set(model, targets, options);
}

EvaluateResult evaluate(const RegistrationModel& model, const MeasuredPoints& targets,
                        const EvaluateOptions& options) {
  EvaluateResult out = evaluate_set(model, targets.to_measurement_set(Role::kTarget, true), options);
  if (targets.names.empty()) {  // no labels given: none invented, bad targets by their number
    out.names.clear();
    for (std::string& bad : out.bad_targets) bad = "#" + bad;
  }
  return out;
}

}  // namespace vrreg
