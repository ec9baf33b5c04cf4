// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/approach.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/planning/monitor_points.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg/planning/robot_program.hpp"

namespace vrreg::planning {
namespace {

constexpr double kMaxOffsetRad = units::deg_to_rad(30.0);

// Sum over consecutive stops of the farthest-moving joint's travel [rad].
double joint_path_rad(const std::vector<ProgramLocation>& stops) {
  double total = 0.0;
  for (std::size_t k = 1; k < stops.size(); ++k) {
    const kinematics::JointVector& to = stops[k].q_rad;
    const kinematics::JointVector& via = stops[k].via_q_rad.value_or(to);
    total += (via - stops[k - 1].q_rad).cwiseAbs().maxCoeff() + (to - via).cwiseAbs().maxCoeff();
  }
  return total;
}

}  // namespace

void ApproachOptions::validate(const kinematics::SerialChain& chain) const {
  if (!enabled()) return;
  VRREG_THROW_UNLESS(direction.size() == chain.n_joints(),
                     "approach: " << direction.size() << " directions for robot '" << chain.name()
                                  << "' with " << chain.n_joints() << " joints");
  for (int j = 0; j < chain.n_joints(); ++j) {
    VRREG_THROW_UNLESS(
        direction(j) == 1.0 || direction(j) == -1.0,
        "approach: the direction of joint " << j + 1 << " must be +1 or -1, got " << direction(j));
    VRREG_THROW_UNLESS(!chain.prismatic(j), "approach: joint "
                                                << j + 1
                                                << " is prismatic; approach "
                                                   "directions need revolute joints");
  }
  VRREG_THROW_UNLESS(std::isfinite(offset_rad) && offset_rad > 0.0 && offset_rad <= kMaxOffsetRad,
                     "approach: the offset must be in (0, 30] deg, got "
                         << units::rad_to_deg(offset_rad) << " deg");
}

kinematics::JointVector approach_via(const kinematics::SerialChain& chain,
                                     const kinematics::JointRef& q_rad,
                                     const ApproachOptions& options) {
  options.validate(chain);
  VRREG_THROW_UNLESS(options.enabled(), "approach: no directions given");
  chain.check_joints(q_rad, "approach");
  kinematics::JointVector via = q_rad;
  for (int j = 0; j < chain.n_joints(); ++j) {
    const kinematics::JointLimits& limit = chain.limit(j);
    const double wanted = q_rad(j) - options.direction(j) * options.offset_rad;
    via(j) = std::clamp(wanted, limit.lower_rad, limit.upper_rad);
    const double room_rad = options.direction(j) * (q_rad(j) - via(j));
    VRREG_THROW_UNLESS(room_rad >= kMinApproachFraction * options.offset_rad,
                       "approach: joint "
                           << j + 1 << " at " << units::rad_to_deg(q_rad(j)) << " deg is "
                           << units::rad_to_deg(std::max(room_rad, 0.0)) << " deg from its limit "
                           << units::rad_to_deg(options.direction(j) > 0 ? limit.lower_rad
                                                                         : limit.upper_rad)
                           << " deg on the side it must come from (needs "
                           << units::rad_to_deg(kMinApproachFraction * options.offset_rad)
                           << " deg); reverse its direction or plan elsewhere");
  }
  return via;
}

void add_approach_vias(const kinematics::SerialChain& chain, PlanResult& plan,
                       const ApproachOptions& options) {
  options.validate(chain);
  if (!options.enabled()) return;
  for (PlannedLocation& l : plan.locations) {
    if (l.via_q_rad) continue;
    try {
      l.via_q_rad = approach_via(chain, l.q_rad, options);
    } catch (const InputError& e) {
      throw InputError("location '" + l.point + "': " + e.what());
    }
    l.via_robot_m = kinematics::forward_kinematics(chain, *l.via_q_rad).translation();
  }
}

ApproachCost approach_cost(const PlanResult& plan, const ProgramOptions& options) {
  std::vector<ProgramLocation> direct;
  std::vector<ProgramLocation> with_vias;
  ApproachCost cost;
  for (const PlannedLocation& l : plan.locations) {
    direct.push_back({l.point, l.role, {}, l.q_rad});
    with_vias.push_back({l.point, l.role, {}, l.q_rad, -1, l.via_q_rad});
    if (l.via_q_rad) ++cost.n_via;
  }
  // The first location's via point counts: the arm reaches the first stop through it.
  if (!with_vias.empty() && with_vias.front().via_q_rad) {
    with_vias.insert(with_vias.begin(), {"", Role::kFiducial, {}, *with_vias.front().via_q_rad});
  }
  cost.joint_path_rad = joint_path_rad(direct);
  cost.joint_path_with_vias_rad = joint_path_rad(with_vias);
  if (!direct.empty()) {
    cost.motion_s = program_duration(direct, options).motion_s;
    cost.motion_with_vias_s = program_duration(with_vias, options).motion_s;
  }
  return cost;
}

}  // namespace vrreg::planning
