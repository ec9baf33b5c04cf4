// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to io: the corrector's lost-motion term (lost_motion_term.hpp) in a model file (the
// corrector's "lost_motion", SI) and in a command's --json (arc-minutes and millimetres).
#include <nlohmann/json.hpp>
#include <string>

#include "json_fields.hpp"
#include "vrreg/correction/lost_motion_term.hpp"

namespace vrreg::io::detail {

/// {"applied", "play_rad" (per joint), "covariance_rad2" (rows), "cv_rms_with_m",
/// "cv_rms_without_m", "judged_by", "n_compared", "reason"}.
nlohmann::ordered_json lost_motion_json(const LostMotionTerm& term);

/// For a command's --json: {"applied", "joints": [{"joint", "play_arcmin", "sd_arcmin"}],
/// "cv_rms_with_mm", "cv_rms_without_mm", "judged_by", "n_compared", "reason"}.
nlohmann::json lost_motion_result_json(const LostMotionTerm& term);

/// Reads what lost_motion_json writes at key path `path`; errors name the file and the key.
LostMotionTerm read_lost_motion(const nlohmann::json& item, const std::string& path,
                                const JsonFields& f);

}  // namespace vrreg::io::detail
