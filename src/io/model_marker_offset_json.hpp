// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to io: the "marker_offset" member of a model file (hand-eye registration).
#include <nlohmann/json.hpp>

#include "json_fields.hpp"
#include "model_units.hpp"
#include "vrreg/pipeline/marker_offset_model.hpp"

namespace vrreg::io::detail {

/// {"p_flange_marker_m", "p_std_m", "flange_robot": {name, dh, joint_limits_rad, base_matrix}}.
nlohmann::ordered_json marker_offset_json(const MarkerOffsetModel& offset);

/// Reads what marker_offset_json writes (at key path `path`), or a version 1 file's millimetres
/// (`units`); errors name the file and the key.
MarkerOffsetModel read_marker_offset(const nlohmann::json& item, const std::string& path,
                                     const JsonFields& f, const LengthUnits& units);

}  // namespace vrreg::io::detail
