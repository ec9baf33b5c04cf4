// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one place where each front-door result becomes its JSON shape (lengths in mm, as
// `vrreg <command> --json` prints them, docs/file-formats.md#outputs) and its one-line brief
// report: used by the command line, Python (to_json(), repr) and the tests. Library text in them
// (layouts, notes) names options as `name` (docs/library.md#errors).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "vrreg/pipeline/correct.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/marker_offset.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"

namespace vrreg::io {

/// register: transform, FRE, sigma_L (Eq. 1), noise and rho (Eq. 9), robust check, the
/// cross-validation table and Procedure 2's figures.
nlohmann::json register_json(const RegisterResult& result);
/// An orientation field: its method, whether it is applied (its cross-validated RMS angle below
/// the uncorrected one), both RMS angles and the methods compared (mrad).
nlohmann::json orientation_field_json(const OrientationCorrector& field);

/// The corrector's lost-motion term for a command's --json: `applied`, `joints` (`joint`,
/// `play_arcmin`, `sd_arcmin`), `cv_rms_with_mm`, `cv_rms_without_mm`, `judged_by`,
/// `n_compared`, `reason`. register_json holds it when the term entered the correction.
nlohmann::json lost_motion_result_json(const LostMotionTerm& term);
/// ISO 9283's multi-directional accuracy: `n_points`, `directions` (`approach`, `n_targets`,
/// `unc_rms_t_mm`, `cor_rms_t_mm`), `unc_spread_max_mm`, `unc_spread_mean_mm`,
/// `cor_spread_max_mm`, `cor_spread_mean_mm`.
nlohmann::json multidirectional_json(const MultidirectionalAccuracy& m);
/// evaluate: RMS_T (Eq. 4) both ways over the corrected targets, gamma, N_bad, the flagged ones
/// apart, the predicted sd and its calibration, the strategy used, and `multidirectional` when
/// some target point was visited from two approach directions.
nlohmann::json evaluate_json(const EvaluateResult& result);
/// The same with the Procedure 2 details only the model knows (joint norm, Strategy 3's
/// registration fiducials and seed), as `vrreg evaluate --json` prints it.
nlohmann::json evaluate_json(const EvaluateResult& result, const RegistrationModel& model);
/// correct: how many points, how many flagged, the method and its layout, the predicted sd.
nlohmann::json correct_json(const CorrectResult& result);
/// The corrected orientations' summary: method, counts by status, the predicted angle sd (median,
/// max) and how many are above the limit (mrad).
nlohmann::json orientation_correction_json(const OrientationCorrection& o);
/// register with the marker offset (hand-eye, docs/hand-eye.md): the offset and its uncertainty
/// (noise, joint offsets, both), the transform and its uncertainty, the marker's orientation when
/// measured, FRE, sigma_L, rho, the fiducials used for the offset only. `result` must be ok().
nlohmann::json marker_offset_register_json(const MarkerOffsetRegisterResult& result);

/// The cross-validation table of `auto` (rows per method: RMS, per axis, or why not applicable).
nlohmann::json cross_validation_json(const CrossValidation& cv);
/// The robust check: its scale and bound, each rejected fiducial with its deviation.
nlohmann::json robust_json(const RobustReport& report);
/// Adds the predicted sd's median and max, and its calibration when given, to `j`.
void add_predicted_sd_json(const TargetCorrection& correction,
                           const std::optional<UncertaintyCalibration>& calibration,
                           nlohmann::json& j);
/// Adds Procedure 2's strategy, joint norm, relabelling and registration fiducials to `j`.
void add_strategy_json(const RegistrationModel& model,
                       const std::optional<planning::Strategy2Summary>& relabelled,
                       nlohmann::json& j);

/// A 3-vector in metres as a JSON array in millimetres.
nlohmann::json json_mm3(const Eigen::Vector3d& m);

/// A location as people name it: its point, and its configuration when it has one.
std::string location_name(const Location& location);

/// One line with the figures a person looks at first, e.g. "register: 519 fiducials, FRE
/// 0.412 mm, sigma_L 0.523 mm, rho 9.12".
std::string brief_report(const RegisterResult& result);
/// "evaluate: 48 targets, grid: RMS_T 0.412 mm uncorrected, 0.133 mm corrected, gamma 67.8 %,
/// N_bad 2, n_flagged 0"; the flagged targets' own RMS_T when there are some.
std::string brief_report(const EvaluateResult& result);
/// "correct: 48 points, grid, n_flagged 0".
std::string brief_report(const CorrectResult& result);

}  // namespace vrreg::io
