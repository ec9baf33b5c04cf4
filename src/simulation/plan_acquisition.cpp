// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/plan_acquisition.hpp"

#include <set>
#include <utility>

#include "acquisition_detail.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::simulation {
namespace {

void check_location(const Testbed& testbed, const CommandedLocation& c, bool with_config) {
  const int n = testbed.nominal.n_joints();
  VRREG_THROW_UNLESS(c.q_rad.size() == n, "plan location '" << c.point << "' has " << c.q_rad.size()
                                                            << " joints; " << testbed.name
                                                            << " has " << n);
  VRREG_THROW_UNLESS(c.q_rad.allFinite() && c.robot_m.allFinite(),
                     "plan location '" << c.point << "' has non-finite joints or position");
  VRREG_THROW_UNLESS(!c.via_q_rad || (c.via_q_rad->size() == n && c.via_q_rad->allFinite()),
                     "plan location '" << c.point << "': its via point has non-finite joints or "
                                       << (c.via_q_rad ? c.via_q_rad->size() : 0) << " of them; "
                                       << testbed.name << " has " << n);
  VRREG_THROW_UNLESS(c.config.has_value() == with_config,
                     "plan location '" << c.point << "': a config on some locations only");
  const Eigen::Vector3d tcp =
      kinematics::forward_kinematics(testbed.nominal, c.q_rad).translation();
  VRREG_THROW_UNLESS((tcp - c.robot_m).norm() <= kPlanTcpToleranceM,
                     "plan location '" << c.point << "': its joints put the " << testbed.name
                                       << " test bed's TCP " << 1e3 * (tcp - c.robot_m).norm()
                                       << " mm from its robot position (a plan for another robot "
                                          "or tool? plan with `robot` "
                                       << testbed.name << ")");
}

}  // namespace

SimulatedDataset simulate_plan(const Testbed& testbed, const std::vector<CommandedLocation>& plan,
                               const SimulationOptions& options) {
  VRREG_THROW_UNLESS(!plan.empty(), "the plan has no locations");
  SimulatedDataset data;
  data.testbed = testbed.name;
  data.dataset = Dataset::kPlan;
  data.seed = options.seed;
  data.errors = options.errors.value_or(testbed.default_errors);
  data.errors.validate(testbed.nominal.n_joints());
  data.sigma_rep_spec_m = testbed.sigma_rep_spec_m;
  data.has_config = plan.front().config.has_value();
  data.marker_flange_m = options.marker_flange_m;
  data.body_mount_rotation_rad = options.body_mount_rotation_rad;
  data.time_s = options.time_s;
  data.events = options.events;
  VRREG_THROW_UNLESS(options.monitor_visits >= 1,
                     "`monitor_visits` must be >= 1, got " << options.monitor_visits);
  std::set<std::pair<std::string, int>> seen;
  std::vector<int> monitors;
  for (std::size_t n = 0; n < plan.size(); ++n) {
    const CommandedLocation& c = plan[n];
    check_location(testbed, c, data.has_config);
    VRREG_THROW_UNLESS(seen.insert({c.point, c.config.value_or(0)}).second,
                       "plan location '" << c.point << "' is listed twice");
    data.locations.push_back({c.point, c.role, c.robot_m, -1, 0.0});
    if (c.role == Role::kMonitor) {
      monitors.push_back(static_cast<int>(n));
      continue;
    }
    data.visits.push_back(
        {static_cast<int>(n), c.config.value_or(0), c.q_rad, Eigen::Vector3d::Zero()});
    data.visits.back().via_q_rad = c.via_q_rad;
  }
  // Monitor points last, in rounds: the arm leaves each and comes back (docs/monitoring.md).
  for (int round = 0; round < options.monitor_visits; ++round) {
    for (const int n : monitors) {
      const CommandedLocation& c = plan[static_cast<std::size_t>(n)];
      data.visits.push_back({n, c.config.value_or(0), c.q_rad, Eigen::Vector3d::Zero(), round});
      data.visits.back().via_q_rad = c.via_q_rad;
    }
  }
  detail::acquire_visits(testbed, data);
  return data;
}

}  // namespace vrreg::simulation
