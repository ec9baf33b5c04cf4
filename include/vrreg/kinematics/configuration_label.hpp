// SPDX-License-Identifier: Apache-2.0
#pragma once
// Stable labels of arm configurations: what an IK branch is, independent of the order in which a
// solver returns it. The index is what measurement files store in their `config` column.
#include <cstdint>
#include <string>
#include <string_view>

namespace vrreg::kinematics {

/// The kind of arm a label describes.
enum class ArmKind : std::uint8_t {
  kUr,
  kLwr,
  kGeneric,  ///< any other chain: signs of its branch joints (numeric_ik.hpp)
};

/// Configuration of a 6R UR arm (three binary choices), a 7R LWR arm (global configuration:
/// signs of theta2, theta4, theta6), index 0..7, or of a generic chain (signs of its branch
/// joints). String like "shoulder-left/elbow-up/wrist-noflip" (UR), "GC=+,-,+" (LWR) or
/// "q3+,q5-" (generic; "single-class" without branch joints).
class ConfigurationLabel {
 public:
  ConfigurationLabel() = default;
  /// Label of `kind` from its index in 0..7 (throws InputError otherwise).
  ConfigurationLabel(ArmKind kind, int index);

  /// UR label. Index bits: 4 = shoulder right, 2 = elbow down, 1 = wrist flipped.
  static ConfigurationLabel ur(bool shoulder_left, bool elbow_up, bool wrist_flipped);
  /// LWR label from the signs (+1 / -1) of theta2, theta4, theta6. Index bits: 4 = theta2 < 0,
  /// 2 = theta4 < 0, 1 = theta6 < 0.
  static ConfigurationLabel lwr(int sign2, int sign4, int sign6);
  /// Generic label: bit k of `joint_mask` marks joint k + 1 as a branch joint, the same bit of
  /// `negative` that its sin(theta) is negative. Index: the negative bits packed in joint order.
  static ConfigurationLabel generic(std::uint16_t joint_mask, std::uint16_t negative);
  /// Parses what to_string() prints; throws InputError on anything else.
  static ConfigurationLabel parse(std::string_view text);

  [[nodiscard]] ArmKind kind() const { return kind_; }
  [[nodiscard]] int index() const;
  [[nodiscard]] std::string to_string() const;

  [[nodiscard]] bool shoulder_left() const { return (bits_ & 4) == 0; }  ///< UR only
  [[nodiscard]] bool elbow_up() const { return (bits_ & 2) == 0; }       ///< UR only
  [[nodiscard]] bool wrist_flipped() const { return (bits_ & 1) != 0; }  ///< UR only
  /// LWR only: sign (+1 / -1) of theta2 (joint 2), theta4 (joint 4) or theta6 (joint 6).
  [[nodiscard]] int lwr_sign(int joint) const;

  friend bool operator==(const ConfigurationLabel&, const ConfigurationLabel&) = default;

 private:
  ArmKind kind_ = ArmKind::kUr;
  std::uint8_t bits_ = 0;
  std::uint16_t joint_mask_ = 0;  ///< generic: the branch joints
  std::uint16_t negative_ = 0;    ///< generic: which of them have sin(theta) < 0
};

}  // namespace vrreg::kinematics
