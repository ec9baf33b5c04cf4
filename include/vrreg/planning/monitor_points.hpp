// SPDX-License-Identifier: Apache-2.0
#pragma once
// Monitor points for a plan: a few of its fiducial locations, spread over the volume and in the
// arm configurations the plan uses, read at registration and again at every check
// (pipeline/check.hpp), each in several visits so that the robot's repeatability averages out.
#include <vector>

#include "vrreg/planning/plan.hpp"
#include "vrreg/planning/robot_program.hpp"

namespace vrreg::planning {

/// Appends `count` monitor locations ("monitor-1" ...; role monitor) to `plan`: copies of its
/// fiducial locations chosen by spread_points (the extremes first), with their joints and
/// configuration. Throws InputError on count < 1 or a plan with fewer fiducials than `count`.
void add_monitor_points(PlanResult& plan, int count);

/// The plan's monitor locations as a program visits them: `visits` rounds over all of them (the
/// arm leaves and comes back between visits of a point), each location labelled with its visit.
std::vector<ProgramLocation> monitor_program_locations(const PlanResult& plan, int visits);

}  // namespace vrreg::planning
