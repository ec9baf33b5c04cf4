// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/configuration_label.hpp"

#include <optional>

#include "vrreg/core/check.hpp"

namespace vrreg::kinematics {

ConfigurationLabel ConfigurationLabel::generic(std::uint16_t joint_mask, std::uint16_t negative) {
  ConfigurationLabel label;
  label.kind_ = ArmKind::kGeneric;
  label.joint_mask_ = joint_mask;
  label.negative_ = static_cast<std::uint16_t>(negative & joint_mask);
  return label;
}

int ConfigurationLabel::index() const {
  if (kind_ != ArmKind::kGeneric) return bits_;
  int index = 0, bit = 0;
  for (int j = 0; j < 16; ++j) {
    if ((joint_mask_ >> j & 1) == 0) continue;
    if ((negative_ >> j & 1) != 0) index |= 1 << bit;
    ++bit;
  }
  return index;
}

ConfigurationLabel::ConfigurationLabel(ArmKind kind, int index) : kind_(kind) {
  VRREG_THROW_UNLESS(kind != ArmKind::kGeneric,
                     "a generic configuration label needs its branch joints (use generic())");
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
  if (kind_ == ArmKind::kGeneric) {
    std::string s;
    for (int j = 0; j < 16; ++j) {
      if ((joint_mask_ >> j & 1) == 0) continue;
      if (!s.empty()) s += ',';
      s += 'q' + std::to_string(j + 1) + ((negative_ >> j & 1) != 0 ? '-' : '+');
    }
    return s.empty() ? "single-class" : s;
  }
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

namespace {

// "q3+,q5-" or "single-class" as a generic label; empty when `text` is not one.
std::optional<ConfigurationLabel> parse_generic(std::string_view text) {
  if (text == "single-class") return ConfigurationLabel::generic(0, 0);
  std::uint16_t mask = 0, negative = 0;
  while (!text.empty()) {
    const std::size_t comma = text.find(',');
    const std::string_view item = text.substr(0, comma);
    if (item.size() < 3 || item.front() != 'q' || (item.back() != '+' && item.back() != '-')) {
      return std::nullopt;
    }
    int joint = 0;
    for (const char c : item.substr(1, item.size() - 2)) {
      if (c < '0' || c > '9' || joint > 16) return std::nullopt;
      joint = 10 * joint + (c - '0');
    }
    if (joint < 1 || joint > 16 || (mask >> (joint - 1) & 1) != 0) return std::nullopt;
    mask = static_cast<std::uint16_t>(mask | 1u << (joint - 1));
    if (item.back() == '-') negative = static_cast<std::uint16_t>(negative | 1u << (joint - 1));
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
    if (text.empty()) return std::nullopt;
  }
  if (mask == 0) return std::nullopt;
  return ConfigurationLabel::generic(mask, negative);
}

}  // namespace

ConfigurationLabel ConfigurationLabel::parse(std::string_view text) {
  if (const std::optional<ConfigurationLabel> generic = parse_generic(text)) return *generic;
  for (int index = 0; index < 8; ++index) {
    for (ArmKind kind : {ArmKind::kUr, ArmKind::kLwr}) {
      const ConfigurationLabel label(kind, index);
      if (label.to_string() == text) return label;
    }
  }
  VRREG_THROW_UNLESS(false, "unknown configuration label '"
                                << text
                                << "' (expected e.g. 'shoulder-left/elbow-up/wrist-noflip', "
                                   "'GC=+,-,+' or 'q3+,q5-')");
  return {};
}

}  // namespace vrreg::kinematics
