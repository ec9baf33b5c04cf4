// SPDX-License-Identifier: Apache-2.0
#pragma once
// The registration model file (`register -o model.json`): JSON with "format": "vrreg-model",
// "version": 1, "units": {"length": "mm", "angle": "rad"}, rotation (3x3 rows), translation_mm,
// scale, fre_mm, sigma_l_mm, sigma_rep_mm (when given to register), config (or null), source, interpolation {method, cube_mm,
// match_tolerance_mm} and fiducials [{point, config, robot_mm, sensor_mm, n_readings,
// sensor_sq_dev_mm2, q_rad (omitted when empty), correction_mm}], and for models built with a
// Procedure 2 strategy (section 4.4) procedure2 {strategy, joint_norm, seed (Strategy 3),
// registration_fiducials (Strategy 3: indices into fiducials)}. Numbers are written in the
// shortest form that reads back exactly; unknown keys are ignored when reading.
#include <string>

#include "vrreg/pipeline/model.hpp"

namespace vrreg::io {

/// The model as JSON text; throws InputError for a model that could not be read back
/// (non-finite numbers, corrections count != fiducials count).
std::string format_model_json(const RegistrationModel& model);

/// Writes format_model_json(model) to `path` atomically (whole or not at all).
void write_model_json(const std::string& path, const RegistrationModel& model);

/// Parses model JSON `text`; `source` names it in errors (FileError "source:line: message").
RegistrationModel parse_model_json(const std::string& text, const std::string& source);

/// Reads the model file at `path`; throws FileError on a missing, truncated or invalid file.
RegistrationModel read_model_json(const std::string& path);

}  // namespace vrreg::io
