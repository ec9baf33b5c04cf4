// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal: fitting one wrapped joint value into its limits by 2 pi shifts.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics::detail {

/// The value q + 2 pi k in [lower, upper] nearest `target`; false when no k fits (q unchanged).
inline bool shift_joint(double& q, const JointLimits& limits, double target) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  if (q >= limits.lower_rad && q <= limits.upper_rad && std::abs(q - target) <= std::numbers::pi) {
    return true;  // already the nearest shift in the limits
  }
  double k_min = std::ceil((limits.lower_rad - q) / kTwoPi);
  double k_max = std::floor((limits.upper_rad - q) / kTwoPi);
  if (q + k_min * kTwoPi < limits.lower_rad) k_min += 1.0;  // rounding of the division
  if (q + k_max * kTwoPi > limits.upper_rad) k_max -= 1.0;
  if (!(k_min <= k_max)) return false;
  const double k = std::clamp(std::round((target - q) / kTwoPi), k_min, k_max);
  q += k * kTwoPi;
  return true;
}

}  // namespace vrreg::kinematics::detail
