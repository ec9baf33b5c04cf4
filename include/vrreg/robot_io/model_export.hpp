// SPDX-License-Identifier: Apache-2.0
#pragma once
// A registration model in the formats robot cells use (`vrreg export`, docs/hand-eye.md):
// easy_handeye-style YAML (x y z qx qy qz qw in metres), a URDF fixed joint, or plain JSON with
// a 4 x 4 matrix. Every format states the direction of the transform in words.
#include <string>

#include "vrreg/pipeline/model.hpp"

namespace vrreg::io {

/// Export formats.
enum class ExportFormat { kYaml, kUrdf, kJson };

/// Parses "yaml", "urdf" or "json"; throws InputError otherwise.
ExportFormat parse_export_format(const std::string& text);

/// The sentence every format carries: what T_robot_sensor maps and which frame is the parent.
extern const char* const kTransformDirection;

/// The model's T_robot_sensor (and marker offset, when estimated) as text in `format`. Throws
/// InputError for a model with a scale (a similarity is not a rigid transform).
std::string export_model(const RegistrationModel& model, ExportFormat format);

}  // namespace vrreg::io
