// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/ik_result.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg::kinematics {

void IkOptions::validate() const {
  VRREG_THROW_UNLESS(
      std::isfinite(singular_tolerance) && singular_tolerance >= 0.0 && singular_tolerance < 1.0,
      "IK options: singular_tolerance must be in [0, 1), got " << singular_tolerance);
  VRREG_THROW_UNLESS(
      std::isfinite(reach_tolerance_m) && reach_tolerance_m >= 0.0,
      "IK options: reach_tolerance_m must be finite and >= 0, got " << reach_tolerance_m);
  VRREG_THROW_UNLESS(
      std::isfinite(singular_free_angle_rad),
      "IK options: singular_free_angle_rad must be finite, got " << singular_free_angle_rad);
}

std::string singularity_names(std::uint8_t flags) {
  if (flags == kNoSingularity) return "none";
  std::string s;
  const auto add = [&](std::uint8_t bit, const char* name) {
    if ((flags & bit) == 0) return;
    if (!s.empty()) s += ',';
    s += name;
  };
  add(kWristSingular, "wrist");
  add(kShoulderSingular, "shoulder");
  add(kElbowSingular, "elbow");
  add(kArmAngleSingular, "arm-angle");
  return s;
}

const char* to_string(IkStatus status) {
  switch (status) {
    case IkStatus::kOk:
      return "ok";
    case IkStatus::kUnreachable:
      return "unreachable";
    case IkStatus::kOutsideLimits:
      return "outside-limits";
  }
  return "unknown";
}

}  // namespace vrreg::kinematics
