#pragma once
// Options in, result out for every analytic IK solver. Unreachable poses and singular cases are
// values in the result, never exceptions; bad caller input throws InputError (design.md 7).
#include <cstdint>
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
  /// Value [rad] given to the free joint at an exact singularity (UR: q6 at sin q5 = 0; LWR:
  /// theta3 at sin theta2 = 0 and theta7 at sin theta6 = 0).
  double singular_free_angle_rad = 0.0;

  /// Throws InputError when a field is out of range.
  void validate() const;
};

/// Bit flags of the singular cases an IK query or a solution touches.
enum Singularity : std::uint8_t {
  kNoSingularity = 0,
  kWristSingular = 1,     ///< UR: sin q5 ~ 0 (q6 free); LWR: sin theta6 ~ 0 (theta5 + theta7 free)
  kShoulderSingular = 2,  ///< UR: wrist centre on the joint-1 axis cylinder; LWR: sin theta2 ~ 0
  kElbowSingular = 4,     ///< UR: sin q3 ~ 0; LWR: theta4 ~ 0 (arm stretched, psi undefined)
  kArmAngleSingular = 8,  ///< LWR: shoulder-wrist axis on the joint-1 axis (reference plane undefined)
};

/// Comma-separated names of the flags set in `flags` ("none" when none).
std::string singularity_names(std::uint8_t flags);

/// Outcome of an IK query.
enum class IkStatus {
  kOk,                 ///< at least one solution
  kUnreachable,        ///< the pose is outside the workspace (see message)
  kOutsideLimits,      ///< solutions exist but none within the joint limits
};

/// Lower-case name of a status ("ok", "unreachable", "outside-limits").
const char* to_string(IkStatus status);

/// One joint-space solution.
struct IkSolution {
  JointVector q_rad;                 ///< joint values [rad], shifted into the limits
  ConfigurationLabel config;         ///< branch label
  std::uint8_t singular = kNoSingularity;  ///< Singularity flags of this solution
};

/// All solutions of one query, ordered by configuration index.
struct IkResult {
  IkStatus status = IkStatus::kUnreachable;
  std::string message;               ///< why there is no solution (empty when ok)
  std::vector<IkSolution> solutions;
  std::uint8_t singular = kNoSingularity;  ///< union of the flags of all branches
  int n_outside_limits = 0;          ///< branches dropped by the joint limits

  [[nodiscard]] bool ok() const { return status == IkStatus::kOk; }
};

}  // namespace vrreg::kinematics
