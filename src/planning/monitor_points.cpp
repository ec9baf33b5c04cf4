// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/monitor_points.hpp"

#include "vrreg/core/check.hpp"
#include "vrreg/planning/spread_points.hpp"

namespace vrreg::planning {

void add_monitor_points(PlanResult& plan, int count) {
  VRREG_THROW_UNLESS(count >= 1, "`monitor` must be >= 1, got " << count);
  std::vector<std::size_t> fiducials;
  for (std::size_t i = 0; i < plan.locations.size(); ++i) {
    if (plan.locations[i].role == Role::kFiducial) fiducials.push_back(i);
  }
  VRREG_THROW_UNLESS(fiducials.size() >= static_cast<std::size_t>(count),
                     "`monitor` " << count << " asks for more monitor points than the plan has "
                                  << "fiducials (" << fiducials.size() << ")");
  Points3 robot(3, static_cast<Eigen::Index>(fiducials.size()));
  for (std::size_t k = 0; k < fiducials.size(); ++k)
    robot.col(static_cast<Eigen::Index>(k)) = plan.locations[fiducials[k]].robot_m;
  int n = 0;
  for (const std::size_t k : spread_points(robot, static_cast<std::size_t>(count))) {
    PlannedLocation m = plan.locations[fiducials[k]];
    m.point = "monitor-" + std::to_string(++n);
    m.role = Role::kMonitor;
    plan.locations.push_back(std::move(m));
  }
}

std::vector<ProgramLocation> monitor_program_locations(const PlanResult& plan, int visits) {
  VRREG_THROW_UNLESS(visits >= 1, "`monitor_visits` must be >= 1, got " << visits);
  std::vector<ProgramLocation> out;
  for (int v = 0; v < visits; ++v) {
    for (const PlannedLocation& l : plan.locations) {
      if (l.role != Role::kMonitor) continue;
      out.push_back({l.point, l.role, l.config.to_string(), l.q_rad, v});
    }
  }
  return out;
}

}  // namespace vrreg::planning
