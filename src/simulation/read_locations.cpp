// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/read_locations.hpp"

#include "vrreg/core/check.hpp"

namespace vrreg::simulation {

std::vector<Location> read_locations(const SimulatedRobot& robot,
                                     const RigidTransform& T_robot_sensor,
                                     const TrackerModel& tracker,
                                     const std::vector<CommandedLocation>& locations, int visits,
                                     Random& rng) {
  VRREG_THROW_UNLESS(visits >= 1, "read locations: needs 1 or more visits, got " << visits);
  tracker.validate();
  const RigidTransform T_sensor_robot = T_robot_sensor.inverse();
  const int k = tracker.readings_per_location;
  std::vector<Location> out;
  if (locations.empty()) return out;
  JointApproach approach(locations.front().q_rad);  // lost motion: the path starts at the first
  for (int v = 0; v < visits; ++v) {
    for (const CommandedLocation& c : locations) {
      Location l;
      l.point = c.point;
      l.role = c.role;
      l.config = c.config;
      if (visits > 1 || c.role == Role::kMonitor) l.visit = v;
      l.robot_m = c.robot_m;
      l.q_rad.assign(c.q_rad.data(), c.q_rad.data() + c.q_rad.size());
      const Eigen::Vector3d tcp = robot.visit_tcp_m(c.q_rad, rng, approach.move_to(c.q_rad));
      for (int r = 0; r < k; ++r) {  // Welford, as a file's repeat readings are averaged
        const Eigen::Vector3d x = tracker_reading(T_sensor_robot, tracker.noise_sigma_m, tcp, rng);
        l.n_readings += 1;
        const Eigen::Vector3d delta = x - l.sensor_m;
        l.sensor_m += delta / static_cast<double>(l.n_readings);
        l.sensor_sq_dev_m2 += delta.cwiseProduct(x - l.sensor_m);
      }
      l.source_line = out.size() + 1;
      out.push_back(std::move(l));
    }
  }
  return out;
}

}  // namespace vrreg::simulation
