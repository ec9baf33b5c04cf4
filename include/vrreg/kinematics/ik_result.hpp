// SPDX-License-Identifier: Apache-2.0
#pragma once
// Options in, result out for every analytic IK solver. Unreachable poses and singular cases are
// values in the result, never exceptions; bad caller input throws InputError (design.md 7).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/joint_vector.hpp"

namespace vrreg::kinematics {

/// Settings shared by the analytic IK solvers.
struct IkOptions {
  /// Drop solutions outside the joint limits (after trying 2 pi shifts).
  bool apply_joint_limits = true;
  /// A joint counts as singular when |sin| of its angle is at most this. Angles found by the
  /// law of cosines (UR q3, LWR theta4) and the UR shoulder angle use 1 - |cos| <= tolerance
  /// instead, because rounding alone leaves |sin| ~ 1e-8 there. Singular branch pairs collapse.
  double singular_tolerance = 1e-9;
  /// Reach tolerance [m]: a pose this far outside the workspace is still solved on its boundary.
  double reach_tolerance_m = 1e-9;
  /// Joint value [rad] given to the free joint at a singularity (UR: q6 when sin q5 ~ 0; LWR:
  /// q3 when sin theta2 ~ 0, q7 when sin theta6 ~ 0; before the configuration flips).
  double singular_free_angle_rad = 0.0;

  /// Throws InputError when a field is out of range.
  void validate() const;
};

/// Bit flags of the singular cases an IK query or a solution touches.
enum Singularity : std::uint8_t {
  kNoSingularity = 0,
  /// UR: sin q5 ~ 0 (joints 4 and 6 aligned, q6 free); LWR: sin theta6 ~ 0 (joints 5, 7 aligned).
  kWristSingular = 1,
  /// UR: wrist centre at distance d4 from the joint-1 axis (the two shoulder branches meet);
  /// LWR: sin theta2 ~ 0 (joints 1 and 3 aligned).
  kShoulderSingular = 2,
  /// UR: sin q3 ~ 0 (arm stretched or folded); LWR: sin theta4 ~ 0 (psi ill-defined).
  kElbowSingular = 4,
  /// LWR: the shoulder-wrist axis lies on the joint-1 axis (the psi reference plane is undefined;
  /// theta1 = 0 is taken for the reference elbow).
  kArmAngleSingular = 8,
};

/// Comma-separated names of the flags set in `flags` ("none" when none).
std::string singularity_names(std::uint8_t flags);

/// Outcome of an IK query.
enum class IkStatus {
  kOk,             ///< at least one solution
  kUnreachable,    ///< the pose is outside the workspace (see message)
  kOutsideLimits,  ///< solutions exist but none within the joint limits
};

/// Lower-case name of a status ("ok", "unreachable", "outside-limits").
const char* to_string(IkStatus status);

/// One joint-space solution.
struct IkSolution {
  JointVector q_rad{};                     ///< joint values [rad], shifted into the limits
  ConfigurationLabel config{};             ///< branch label
  std::uint8_t singular = kNoSingularity;  ///< Singularity flags of this solution
  std::optional<double> psi_rad{};         ///< LWR with a free arm angle: the one chosen [rad]
};

/// All solutions of one query, ordered by configuration index.
struct IkResult {
  IkStatus status = IkStatus::kUnreachable;
  std::string message{};  ///< why there is no solution (empty when ok)
  std::vector<IkSolution> solutions{};
  std::uint8_t singular = kNoSingularity;  ///< union of the flags of all branches
  int n_outside_limits = 0;                ///< branches dropped by the joint limits

  [[nodiscard]] bool ok() const { return status == IkStatus::kOk; }
};

}  // namespace vrreg::kinematics
