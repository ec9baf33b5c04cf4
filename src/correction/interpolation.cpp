// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/interpolation.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {

void InterpolationSettings::validate() const {
  VRREG_THROW_UNLESS(std::isfinite(match_tolerance_m) && match_tolerance_m > 0.0,
                     "the match tolerance must be > 0, got " << match_tolerance_m << " m");
  VRREG_THROW_UNLESS(std::isfinite(cube_edge_m) && cube_edge_m >= 0.0,
                     "the octuplet cube edge must be finite and >= 0, got " << cube_edge_m << " m");
  VRREG_THROW_UNLESS(method != InterpolationMethod::kOctuplet || cube_edge_m > 0.0,
                     "octuplet interpolation needs a cube edge (`cube_edge`)");
}

const char* to_string(InterpolationMethod method) {
  switch (method) {
    case InterpolationMethod::kLinear: return "linear";
    case InterpolationMethod::kOctuplet: return "octuplet";
    case InterpolationMethod::kGrid: return "grid";
    case InterpolationMethod::kScattered: return "scattered";
    case InterpolationMethod::kTrilinear: return "trilinear";
    case InterpolationMethod::kKriging: return "kriging";
    case InterpolationMethod::kRbf: return "rbf";
    case InterpolationMethod::kJoint: return "joint";
    case InterpolationMethod::kAuto: return "auto";
  }
  return "linear";
}

InterpolationMethod parse_interpolation_method(const std::string& name, bool legacy_auto) {
  if (name == "auto") return legacy_auto ? InterpolationMethod::kLinear : InterpolationMethod::kAuto;
  for (const InterpolationMethod m :
       {InterpolationMethod::kLinear, InterpolationMethod::kOctuplet, InterpolationMethod::kGrid,
        InterpolationMethod::kScattered, InterpolationMethod::kTrilinear,
        InterpolationMethod::kKriging, InterpolationMethod::kRbf, InterpolationMethod::kJoint}) {
    if (name == to_string(m)) return m;
  }
  VRREG_THROW_UNLESS(false, "unknown interpolation method '"
                                << name
                                << "' (expected linear, grid, scattered, octuplet, trilinear, "
                                   "kriging, rbf, joint or auto)");
}

bool is_field_model(InterpolationMethod method) {
  switch (method) {
    case InterpolationMethod::kTrilinear:
    case InterpolationMethod::kKriging:
    case InterpolationMethod::kRbf:
    case InterpolationMethod::kJoint:
    case InterpolationMethod::kAuto: return true;
    default: return false;
  }
}

}  // namespace vrreg
