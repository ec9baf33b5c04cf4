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
                     "octuplet interpolation needs a cube edge (--cube-mm EDGE)");
}

const char* to_string(InterpolationMethod method) {
  switch (method) {
    case InterpolationMethod::kAuto: return "auto";
    case InterpolationMethod::kOctuplet: return "octuplet";
    case InterpolationMethod::kGrid: return "grid";
    case InterpolationMethod::kScattered: return "scattered";
  }
  return "auto";
}

InterpolationMethod parse_interpolation_method(const std::string& name) {
  if (name == "auto") return InterpolationMethod::kAuto;
  if (name == "octuplet") return InterpolationMethod::kOctuplet;
  if (name == "grid") return InterpolationMethod::kGrid;
  if (name == "scattered") return InterpolationMethod::kScattered;
  VRREG_THROW_UNLESS(false, "unknown interpolation method '"
                                << name << "' (expected auto, octuplet, grid or scattered)");
}

}  // namespace vrreg
