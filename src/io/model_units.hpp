// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to io: the length unit of a model file's keys. Version 2 writes metres, so that every
// number reads back to the bit (version 1's millimetres came back one unit in the last place off
// for about 15 % of the values, and a model saved again drifted); version 1 is still read.
#include <string>

namespace vrreg::io::detail {

struct LengthUnits {
  const char* suffix;       ///< of a length key: "_m" or "_mm"
  const char* area_suffix;  ///< of a squared length: "_m2" or "_mm2"
  double per_m;             ///< file units per metre: a length is read as value / per_m
  [[nodiscard]] std::string key(const std::string& base) const { return base + suffix; }
  [[nodiscard]] std::string area_key(const std::string& base) const { return base + area_suffix; }
};

inline constexpr LengthUnits kMetres{"_m", "_m2", 1.0};
inline constexpr LengthUnits kMillimetres{"_mm", "_mm2", 1000.0};

}  // namespace vrreg::io::detail
