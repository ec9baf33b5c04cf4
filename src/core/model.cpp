#include "vrreg/core/model.hpp"

#include "vrreg/core/check.hpp"

namespace vrreg {

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
