// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal: lengths in IK refusals. A far target's distance may overflow in millimetres.
#include <cmath>
#include <string>

#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::kinematics::detail {

/// `m` [m] as "<value> mm" to 6 significant digits, or in metres when millimetres overflow.
inline std::string mm(double m) {
  const double millimetres = units::m_to_mm(m);
  if (std::isfinite(millimetres) || !std::isfinite(m))
    return format_general(millimetres, 6) + " mm";
  return format_general(m, 6) + " m";
}

}  // namespace vrreg::kinematics::detail
