// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading commanded locations with a given robot (grown or not) and tracker pose (bumped or not),
// in visits: the monitor acquisitions of a simulated cell, and the fiducials an update reads.
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"
#include "vrreg/simulation/simulated_robot.hpp"
#include "vrreg/simulation/tracker_model.hpp"

namespace vrreg::simulation {

/// Reads `locations` in turn, `visits` times over (the arm leaves and comes back: a new
/// repeatability draw each visit), K readings per visit, with the tracker at `T_robot_sensor`.
/// One Location per (location, visit): role as commanded, visit index when visits > 1 or the
/// role is monitor, mean reading, squared deviations, joints. Lost motion follows the path from
/// the first location (every joint centred in its play there).
std::vector<Location> read_locations(const SimulatedRobot& robot,
                                     const RigidTransform& T_robot_sensor,
                                     const TrackerModel& tracker,
                                     const std::vector<CommandedLocation>& locations, int visits,
                                     Random& rng);

}  // namespace vrreg::simulation
