// SPDX-License-Identifier: Apache-2.0
#pragma once
// One approach direction per joint (the metrology practice against lost motion, gear backlash):
// before every location the arm first goes to a via point in joint space, the location's joints
// minus direction * offset, so that each joint arrives moving in its chosen direction and rests on
// the same side of its play at every location. The lost motion is then a constant offset per
// joint instead of one that flips with the path (docs/joint-space-model.md, "Lost motion").
#include <Eigen/Core>

#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::planning {

struct PlanResult;
struct ProgramOptions;

/// A via point must leave each joint at least this fraction of the offset to travel (a location
/// nearer its joint limit than that, on the side the joint comes from, is refused).
inline constexpr double kMinApproachFraction = 0.5;

/// Approach directions.
struct ApproachOptions {
  /// Per joint variable +1 or -1: the direction in which it arrives; empty = off.
  kinematics::JointVector direction{};
  double offset_rad = units::deg_to_rad(2.0);  ///< via point's distance per joint [rad]
  [[nodiscard]] bool enabled() const { return direction.size() > 0; }
  /// Throws InputError unless off, or one +-1 per joint of `chain` (all revolute) and an offset
  /// in (0, 30] deg.
  void validate(const kinematics::SerialChain& chain) const;
};

/// The via point before a location with joints `q_rad` [rad]: q - direction * offset, each joint
/// clamped into its limits. Throws InputError naming the joint when the clamp leaves less than
/// kMinApproachFraction of the offset (the location sits at that joint's limit).
kinematics::JointVector approach_via(const kinematics::SerialChain& chain,
                                     const kinematics::JointRef& q_rad,
                                     const ApproachOptions& options);

/// Sets PlannedLocation::via_q_rad (and its nominal TCP) for every location of `plan` that has
/// none; nothing when options are off. Throws InputError naming the location (approach_via).
void add_approach_vias(const kinematics::SerialChain& chain, PlanResult& plan,
                       const ApproachOptions& options);

/// What the via points cost on the robot: joint path and movej time over the plan's locations in
/// order (monitor points once, as listed), without and with the via points.
struct ApproachCost {
  long long n_via = 0;
  /// Sum over the moves of the farthest-moving joint's travel (what sets a movej's time) [rad].
  double joint_path_rad = 0.0;
  double joint_path_with_vias_rad = 0.0;
  double motion_s = 0.0;  ///< movej time at the options' joint speed and acceleration [s]
  double motion_with_vias_s = 0.0;
};

/// The cost of `plan`'s via points at `options`' joint speed (program_duration's movej model).
ApproachCost approach_cost(const PlanResult& plan, const ProgramOptions& options);

}  // namespace vrreg::planning
