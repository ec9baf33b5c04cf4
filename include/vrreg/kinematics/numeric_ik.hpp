// SPDX-License-Identifier: Apache-2.0
#pragma once
// Numerical IK for any chain (revolute and prismatic joints, any number up to kMaxJoints):
// damped least squares (Levenberg-Marquardt on the 6-D pose error, joints projected into their
// limits) from seeded random starts, one solution kept per configuration class. Classes are the
// signs of sin(theta) of the chain's branch joints: the joints at whose 0 and pi two other joint
// axes become parallel (a wrist, a spherical shoulder) or two links of a planar pair line up (an
// elbow), read off the DH table. Which classes are reached is a matter of the restarts: the
// result lists those found, never claims the others do not exist.
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>

#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Settings of the numerical IK.
struct NumericIkOptions {
  bool apply_joint_limits = true;  ///< search within the limits (else revolute joints are free)
  int max_starts = 64;             ///< random starts at most (after `q_start`, if given)
  /// Stop once this many starts in a row converged to classes already found.
  int patience = 24;
  int max_solutions = 64;     ///< stop once this many classes are found (1: the first solution)
  int max_iterations = 1000;  ///< damped steps per start (a joint limit or a stretched arm
                              ///< on the way can take several hundred)
  std::uint64_t seed = 1;     ///< of the random starts: the same seed, the same result
  /// A start converged when |dp| is below this and the rotation error below the next; at a
  /// workspace boundary (a stretched arm) rounding keeps the error near 1e-13.
  double position_tolerance_m = 5e-13;
  double rotation_tolerance_rad = 5e-13;  ///< see position_tolerance_m
  /// Throws InputError on a value out of range.
  void validate() const;
};

/// Solutions of `T_base_tcp` (base frame, m), one per configuration class found, ordered by
/// class index; `q_start_rad` (e.g. the current joints) is tried first. kUnreachable with a
/// message when no start converged (the pose may still be reachable).
IkResult numeric_inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                                    const NumericIkOptions& options = {},
                                    const std::optional<JointVector>& q_start_rad = std::nullopt);

/// Bit k set: joint variable k + 1 turns a branch joint of `chain` (see above; on a coupled chain
/// the variable a branch DH row follows).
std::uint16_t branch_joints(const SerialChain& chain);

/// The generic configuration label of `q_rad` [rad] on `chain` (any family): the sign of
/// sin(theta) of each branch row, labelled by the joint variable it follows.
ConfigurationLabel generic_configuration(const SerialChain& chain, const JointRef& q_rad);

}  // namespace vrreg::kinematics
