// SPDX-License-Identifier: Apache-2.0
#pragma once
// Nominal parameter sets of the robots the paper and its users work with (design.md section 4).
// Base = DH base frame and TCP = flange in all of them; joint limits are the manufacturer's.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Universal Robots UR3 (CB3), joints +-2 pi (joint 6 is unlimited on the robot).
SerialChain ur3();
/// Universal Robots UR5 (CB3), joints +-2 pi.
SerialChain ur5();
/// Universal Robots UR10 (CB3), joints +-2 pi.
SerialChain ur10();
/// Universal Robots UR5e, joints +-2 pi.
SerialChain ur5e();
/// KUKA LWR 4+: joints 1, 3, 5, 7 within +-170 deg, joints 2, 4, 6 within +-120 deg.
SerialChain lwr4();

/// The built-in chain called `name` (ur3, ur5, ur10, ur5e, lwr4; case-insensitive), if any.
std::optional<SerialChain> robot_by_name(std::string_view name);
/// Names robot_by_name() accepts, in a fixed order.
const std::vector<std::string>& builtin_robot_names();

}  // namespace vrreg::kinematics
