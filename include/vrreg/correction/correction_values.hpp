// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a corrector's values are, for the units its description prints them in.

namespace vrreg {

/// What a corrector's values are: the positions' corrections [m], or the orientations' rotation
/// vectors on the tangent space (orientation_field.hpp) [rad]. Only descriptions read it.
enum class CorrectionValues { kLengthM, kRotationRad };
/// The unit a description prints such values in at 1e3 ("mm", "mrad") and at 1e6 ("um", "urad").
inline const char* milli_unit(CorrectionValues values) {
  return values == CorrectionValues::kRotationRad ? "mrad" : "mm";
}
inline const char* micro_unit(CorrectionValues values) {
  return values == CorrectionValues::kRotationRad ? "urad" : "um";
}

}  // namespace vrreg
