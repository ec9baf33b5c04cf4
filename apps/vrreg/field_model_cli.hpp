// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared by evaluate, correct and register: printing the field models' cross-validation table
// and predicted uncertainties (docs/field-models.md); their JSON is io/result_json.hpp's.
#include <optional>

#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/metrics/uncertainty_calibration.hpp"
#include "vrreg/pipeline/field_model.hpp"

namespace vrreg::cli {

/// The table `--interpolation auto` printed: method, CV RMS (3D and per axis), time, choice.
void print_cross_validation(const CrossValidation& cv);

/// Median and max of the predicted sd, and, when targets were measured, the calibration.
void print_predicted_sd(const TargetCorrection& c,
                        const std::optional<UncertaintyCalibration>& calibration);

/// Why the flagged points of `c` were not corrected, for evaluate's and correct's summary:
/// "too few fiducials" when none could be, else "outside the fiducials".
const char* why_not_correctable(const TargetCorrection& c);

}  // namespace vrreg::cli
