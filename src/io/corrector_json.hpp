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

/// A fingerprint of a JSON value: FNV-1a (64 bits, 16 hex digits) over its members in key order
/// and its numbers' values, so that a value written and read back keeps it.
std::string json_fingerprint(const nlohmann::json& value);
std::string json_fingerprint(const nlohmann::ordered_json& value);

/// {"method", "requested": {method, cube_m, match_tolerance_m}, "nearest_configuration",
/// "cv_folds", "cv_seed", "sd_source", "cv_rms_m", "cv_squared_error_m2" (null where not
/// predicted), "cross_validation" (auto: the table without times), "guard" (guard_json.hpp), "state": {key: number, text
/// or {"shape": [rows, cols], "values": column-major}}, "fitted_from": {"method",
/// "fiducials_fnv1a64" (`fiducials_fingerprint`), "state_fnv1a64"}}.
nlohmann::ordered_json corrector_json(const SavedCorrector& saved,
                                      const std::string& fiducials_fingerprint);

/// Reads what corrector_json writes at key path `path`; errors name the file and the key. The
/// state must be the method's (its keys), kriging's length scales positive, and, when the file
/// says what the corrector was fitted from, the method, `fiducials_fingerprint` (of the file's
/// fiducials) and the state's fingerprint must be the ones written.
SavedCorrector read_corrector(const nlohmann::json& item, const std::string& path,
                              const JsonFields& f, const std::string& fiducials_fingerprint);

/// The "orientation_corrector" member (rigid-body markers): {"method", "mean_residual" (9
/// numbers, row-major), "joint_rms_rad", "tangent" (as corrector_json; absent for joint)}.
nlohmann::ordered_json orientation_corrector_json(const SavedOrientationCorrector& saved,
                                                  const std::string& fiducials_fingerprint);

/// Reads what orientation_corrector_json writes at key path `path`.
SavedOrientationCorrector read_orientation_corrector(const nlohmann::json& item,
                                                     const std::string& path, const JsonFields& f,
                                                     const std::string& fiducials_fingerprint);

}  // namespace vrreg::io::detail
