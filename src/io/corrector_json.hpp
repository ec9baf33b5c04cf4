// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to io: the "corrector" member of a model file (version 2): the fitted correction
// method's saved state, its settings, its cross-validation table and where its sd comes from.
#include <nlohmann/json.hpp>
#include <string>

#include "json_fields.hpp"
#include "vrreg/correction/corrector.hpp"
#include "vrreg/correction/orientation_field.hpp"

namespace vrreg::io::detail {

/// {"method", "requested": {method, cube_m, match_tolerance_m}, "nearest_configuration",
/// "cv_folds", "cv_seed", "sd_source", "cv_rms_m", "cv_squared_error_m2" (null where not
/// predicted), "cross_validation" (auto: the table without times), "state": {key: number, text
/// or {"shape": [rows, cols], "values": column-major}}}.
nlohmann::ordered_json corrector_json(const SavedCorrector& saved);

/// Reads what corrector_json writes at key path `path`; errors name the file and the key.
SavedCorrector read_corrector(const nlohmann::json& item, const std::string& path,
                              const JsonFields& f);

/// The "orientation_corrector" member (rigid-body markers): {"method", "mean_residual" (9
/// numbers, row-major), "joint_rms_rad", "tangent" (as corrector_json; absent for joint)}.
nlohmann::ordered_json orientation_corrector_json(const SavedOrientationCorrector& saved);

/// Reads what orientation_corrector_json writes at key path `path`.
SavedOrientationCorrector read_orientation_corrector(const nlohmann::json& item,
                                                     const std::string& path, const JsonFields& f);

}  // namespace vrreg::io::detail
