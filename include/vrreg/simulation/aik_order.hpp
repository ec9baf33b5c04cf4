// SPDX-License-Identifier: Apache-2.0
#pragma once
// The order in which the KUKA's analytic IK module lists the configurations of one pose (paper
// section 4.2: "in an arbitrary order"). The emulated module ranks them by joint-space distance
// (L2, wrapped) from the robot's home posture. That order is the same from point to point except
// where two configurations are equally far from home; there it changes for a whole region, which
// Strategy 2 (reordering along the path) then has to undo. Never a random shuffle.
#include <vector>

#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/joint_vector.hpp"

namespace vrreg::simulation {

/// `solutions` sorted by L2 joint distance to `home_q_rad` [rad], nearest first (ties keep
/// their order); the position in the result + 1 is the configuration label the module reports.
std::vector<kinematics::IkSolution> aik_order(std::vector<kinematics::IkSolution> solutions,
                                              const kinematics::JointRef& home_q_rad);

}  // namespace vrreg::simulation
