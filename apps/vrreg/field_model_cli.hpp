// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared by evaluate, correct and register: printing the field models' cross-validation table
// and predicted uncertainties (docs/field-models.md); their JSON is io/result_json.hpp's.
#include <optional>

#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/lost_motion_term.hpp"
#include "vrreg/correction/orientation_field.hpp"
#include "vrreg/metrics/uncertainty_calibration.hpp"
#include "vrreg/pipeline/field_model.hpp"

namespace vrreg::cli {

/// The table `--interpolation auto` printed: method, CV RMS (3D and per axis), time, choice.
void print_cross_validation(const CrossValidation& cv);

/// Median and max of the predicted sd, and, when targets were measured, the calibration.
void print_predicted_sd(const TargetCorrection& c,
                        const std::optional<UncertaintyCalibration>& calibration);

/// Why the flagged points of `c` were not corrected, for evaluate's and correct's summary:
/// "too few fiducials" or "flat layout" when none could be, "correction not better than none"
/// when the guard held the correction back, else "outside the fiducials".
const char* why_not_correctable(const TargetCorrection& c);

/// The guard's line: applied or not, the cross-validated and the uncorrected RMS it compared,
/// or why it could not judge.
void print_guard(const CorrectionGuard& guard);

/// register's lines on the lost-motion term: per joint the play in arc-minutes with its sd, and
/// whether it entered (the cross-validated RMS with and without it).
void print_lost_motion(const LostMotionTerm& term);

/// register's lines on the orientation field: method, cross-validated and uncorrected RMS angle,
/// whether it is applied, and the methods compared.
void print_orientation_field(const OrientationCorrector& field);

/// correct's line on the corrected orientations: how many, the predicted angle sd and how many
/// are above the limit, or why none were corrected.
void print_orientation_correction(const OrientationCorrection& o);

}  // namespace vrreg::cli
