// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared by simulate_dataset and simulate_plan: the acquisition once the visits are planned.
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::simulation::detail {

/// Draws the robot of data.seed from data.errors (stream 0), places the tracker, and lands and
/// reads every planned visit of `data` K times (streams per data.dataset): fills data.robot,
/// data.T_robot_sensor, each visit's tcp_m and data.readings.
void acquire_visits(const Testbed& testbed, SimulatedDataset& data);

}  // namespace vrreg::simulation::detail
