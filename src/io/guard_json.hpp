// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to io: the correction guard's figures in a model file (the corrector's "guard") and in
// the commands' --json output.
#include <nlohmann/json.hpp>
#include <string>

#include "json_fields.hpp"
#include "vrreg/correction/correction_guard.hpp"

namespace vrreg::io::detail {

/// {"judged", "applied", "judged_by", "cv_rms_m", "uncorrected_rms_m", "n_judged", "note"}.
nlohmann::ordered_json guard_json(const CorrectionGuard& guard);

/// The same in millimetres for a command's --json ("cv_rms_mm", "uncorrected_rms_mm").
nlohmann::json guard_result_json(const CorrectionGuard& guard);

/// Reads what guard_json writes at key path `path`; errors name the file and the key.
CorrectionGuard read_guard(const nlohmann::json& item, const std::string& path,
                           const JsonFields& f);

}  // namespace vrreg::io::detail
