// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/configuration_label.hpp"

#include "vrreg/core/check.hpp"

namespace vrreg::kinematics {

ConfigurationLabel::ConfigurationLabel(ArmKind kind, int index) : kind_(kind) {
  VRREG_THROW_UNLESS(index >= 0 && index < 8, "configuration index must be in 0..7, got " << index);
  bits_ = static_cast<std::uint8_t>(index);
}

ConfigurationLabel ConfigurationLabel::ur(bool shoulder_left, bool elbow_up, bool wrist_flipped) {
  return {ArmKind::kUr, (shoulder_left ? 0 : 4) | (elbow_up ? 0 : 2) | (wrist_flipped ? 1 : 0)};
}

ConfigurationLabel ConfigurationLabel::lwr(int sign2, int sign4, int sign6) {
  return {ArmKind::kLwr, (sign2 < 0 ? 4 : 0) | (sign4 < 0 ? 2 : 0) | (sign6 < 0 ? 1 : 0)};
}

int ConfigurationLabel::lwr_sign(int joint) const {
  VRREG_THROW_UNLESS(joint == 2 || joint == 4 || joint == 6,
                     "LWR configuration signs exist for joints 2, 4 and 6, not " << joint);
  const int bit = joint == 2 ? 4 : (joint == 4 ? 2 : 1);
  return (bits_ & bit) != 0 ? -1 : 1;
}

std::string ConfigurationLabel::to_string() const {
  if (kind_ == ArmKind::kLwr) {
    std::string s = "GC=";
    s += (bits_ & 4) != 0 ? '-' : '+';
    s += ',';
    s += (bits_ & 2) != 0 ? '-' : '+';
    s += ',';
    s += (bits_ & 1) != 0 ? '-' : '+';
    return s;
  }
  std::string s = shoulder_left() ? "shoulder-left" : "shoulder-right";
  s += elbow_up() ? "/elbow-up" : "/elbow-down";
  s += wrist_flipped() ? "/wrist-flip" : "/wrist-noflip";
  return s;
}

ConfigurationLabel ConfigurationLabel::parse(std::string_view text) {
  for (int index = 0; index < 8; ++index) {
    for (ArmKind kind : {ArmKind::kUr, ArmKind::kLwr}) {
      const ConfigurationLabel label(kind, index);
      if (label.to_string() == text) return label;
    }
  }
  VRREG_THROW_UNLESS(false, "unknown configuration label '"
                                << text
                                << "' (expected e.g. 'shoulder-left/elbow-up/wrist-noflip' or "
                                   "'GC=+,-,+')");
  return {};
}

}  // namespace vrreg::kinematics
