// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a Universal Robots controller writes for the numbers of `vrreg snippet urscript`'s
// requests, emulated with 32-bit floats (URScript's float type): the snippet's
// vrreg_text(v, scale), and str_cat of a float alone (6 significant digits).
#include <cmath>
#include <string>

#include "vrreg/core/format.hpp"

namespace vrreg::testing {

/// vrreg_text(v, scale) of the snippet, step by step in float32 and int32 as the program runs.
inline std::string urscript_vrreg_text(float v, int scale) {
  std::string sign;
  float a = v;
  if (v < 0.0f) {
    sign = "-";
    a = -v;
  }
  int whole = static_cast<int>(std::floor(a));
  int fraction = static_cast<int>(
      std::floor((a - static_cast<float>(whole)) * static_cast<float>(scale) + 0.5f));
  if (fraction >= scale) {
    whole = whole + 1;
    fraction = fraction - scale;
  }
  std::string digits = std::to_string(fraction);
  for (int place = 10; place < scale; place *= 10) {
    if (fraction < place) digits = "0" + digits;
  }
  return sign + std::to_string(whole) + "." + digits;
}

/// str_cat of a float: 6 significant digits.
inline std::string urscript_str_cat_float(float v) { return format_general(v, 6); }

}  // namespace vrreg::testing
