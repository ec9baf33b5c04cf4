// SPDX-License-Identifier: Apache-2.0
#pragma once
// Measuring a plan (Procedure 1, paper section 6; `vrreg simulate TESTBED --plan plan.csv`) on a
// simulated test bed, so that a plan's accuracy can be predicted before the robot runs it: the
// robot is sent to each location with the plan's commanded joints, and the tracker reads it K
// times.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::simulation {

/// One location of a plan as a robot program is told it.
struct CommandedLocation {
  std::string point{};  ///< label, unique per (point, config)
  Role role = Role::kFiducial;
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();  ///< nominal TCP position, base frame [m]
  std::optional<int> config{};      ///< the plan's configuration label (all locations or none)
  kinematics::JointVector q_rad{};  ///< commanded joints [rad]
  /// A via point the robot is sent to just before, never read (approach directions) [rad].
  std::optional<kinematics::JointVector> via_q_rad{};
};

/// How far the nominal model's TCP for a location's joints may be from its robot_m [m].
inline constexpr double kPlanTcpToleranceM = 1e-5;

/// Measures `plan` in its order on `testbed` (dataset kPlan): joints as commanded, the robot and
/// noise of options.seed, K readings per visit. Throws InputError on an empty plan, joints of the
/// wrong count or not finite, config on some locations only, a repeated (point, config), or joints
/// whose nominal TCP is more than kPlanTcpToleranceM from robot_m (a plan for another robot or
/// tool).
SimulatedDataset simulate_plan(const Testbed& testbed, const std::vector<CommandedLocation>& plan,
                               const SimulationOptions& options = {});

}  // namespace vrreg::simulation
