// SPDX-License-Identifier: Apache-2.0
#pragma once
// Monitor points for a plan: a few of its fiducial locations, spread over the volume and in the
// arm configurations the plan uses, read at registration and again at every check
// (pipeline/check.hpp), each in several visits so that the robot's repeatability averages out.
// Four by default, not on one plane: three always lie on a plane, and a change along its normal
// that is zero on it (the robot tilting or stretching out of that plane) moves none of them.
#include <vector>

#include "vrreg/planning/plan.hpp"
#include "vrreg/planning/robot_program.hpp"

namespace vrreg::planning {

/// How many monitor points a plan gets when the count is not given: 4, off one plane.
inline constexpr int kDefaultMonitorPoints = 4;

/// The monitor points chosen.
struct MonitorChoice {
  int count = 0;
  double off_plane_rms_m = 0.0;  ///< RMS distance of the points from their best plane [m]
  /// On one plane (always for 3 or fewer; for more, when the plan's fiducials offer no point off
  /// it by more than 1 % of the points' extent).
  bool coplanar = true;
};

/// Appends `count` monitor locations ("monitor-1" ...; role monitor) to `plan`: copies of its
/// fiducial locations chosen by spread_points (the extremes first), with their joints and
/// configuration; with 4 or more, the fourth is the fiducial farthest from the plane of the first
/// three. Throws InputError on count < 1 or a plan with fewer fiducials than `count`.
MonitorChoice add_monitor_points(PlanResult& plan, int count);

/// The plan's monitor locations as a program visits them: `visits` rounds over all of them (the
/// arm leaves and comes back between visits of a point), each location labelled with its visit.
std::vector<ProgramLocation> monitor_program_locations(const PlanResult& plan, int visits);

/// The tracker's reading rate a program's duration assumes [Hz] (OptiTrack-like, as simulated).
inline constexpr double kTrackerRateHz = 120.0;

/// How long a program takes on the robot [s].
struct ProgramDuration {
  int stops = 0;          ///< locations visited
  double motion_s = 0.0;  ///< joint moves between them (from the first; the way to it not counted)
  double settle_s = 0.0;  ///< the settling pauses
  double readings_s = 0.0;  ///< the tracker's readings at `reading_rate_hz`
  [[nodiscard]] double total_s() const { return motion_s + settle_s + readings_s; }
};

/// The time of one joint move as URScript's movej makes it: the joint that moves farthest, at
/// `options.joint_speed_rad_s` and `joint_accel_rad_s2` (trapezoidal, or triangular when short),
/// sets it; then options.settle_s and options.repeats readings at `reading_rate_hz` per stop
/// (the operator's confirmation not counted). Throws InputError on a bad rate or options.
ProgramDuration program_duration(const std::vector<ProgramLocation>& locations,
                                 const ProgramOptions& options,
                                 double reading_rate_hz = kTrackerRateHz);

}  // namespace vrreg::planning
