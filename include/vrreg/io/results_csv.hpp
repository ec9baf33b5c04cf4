// SPDX-License-Identifier: Apache-2.0
#pragma once
// The result files of evaluate and correct (docs/file-formats.md): per-target errors and
// corrected robot-frame positions, in mm, written whole or not at all.
#include <string>

#include "vrreg/pipeline/correct.hpp"
#include "vrreg/pipeline/evaluate.hpp"

namespace vrreg::io {

/// point,config,status,unc_tre_mm,cor_tre_mm,delta_tre_mm,corrected_robot_{x,y,z}_mm,
/// correction_{x,y,z}_mm: one row per evaluated target (10 significant digits).
std::string format_per_target_csv(const EvaluateResult& result);
void write_per_target_csv(const std::string& path, const EvaluateResult& result);

/// A comment naming the model, the points and the interpolation, then point,config,status,
/// robot_{x,y,z}_mm (what to command), uncorrected_robot_{x,y,z}_mm, correction_{x,y,z}_mm
/// (12 significant digits), predicted_sd_mm for field models; with orientations (rigid-body
/// markers) robot_qx..qw (the corrected orientation to command, robot frame),
/// rotation_{x,y,z}_mrad (the applied rotation) and predicted_angle_sd_mrad.
std::string format_corrected_csv(const CorrectResult& result, const std::string& model_name,
                                 const std::string& points_name);
void write_corrected_csv(const std::string& path, const CorrectResult& result,
                         const std::string& model_name, const std::string& points_name);

}  // namespace vrreg::io
