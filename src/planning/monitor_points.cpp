// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/monitor_points.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/planning/spread_points.hpp"

namespace vrreg::planning {
namespace {

// RMS distance of the points from their best plane, and their extent along the widest axis.
std::pair<double, double> off_plane(const Points3& points) {
  const Points3 centred = points.colwise() - points.rowwise().mean();
  const Eigen::Vector3d eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centred * centred.transpose())
          .eigenvalues()
          .cwiseMax(0.0);
  const double n = static_cast<double>(points.cols());
  return {std::sqrt(eigenvalues(0) / n), std::sqrt(eigenvalues(2) / n)};
}

// The time of a movej over `distance_rad` on the joint that moves farthest [s].
double move_time_s(double distance_rad, double speed, double accel) {
  if (distance_rad <= 0.0) return 0.0;
  if (distance_rad >= speed * speed / accel) return distance_rad / speed + speed / accel;
  return 2.0 * std::sqrt(distance_rad / accel);
}

}  // namespace

MonitorChoice add_monitor_points(PlanResult& plan, int count) {
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
  std::vector<std::size_t> chosen = spread_points(robot, static_cast<std::size_t>(count));
  if (count >= 4) {
    // The fourth off the first three's plane: farthest from it (the extremes may share a face).
    const Eigen::Vector3d a = robot.col(static_cast<Eigen::Index>(chosen[0]));
    const Eigen::Vector3d normal = (robot.col(static_cast<Eigen::Index>(chosen[1])) - a)
                                       .cross(robot.col(static_cast<Eigen::Index>(chosen[2])) - a);
    if (normal.norm() > 0.0) {
      const Eigen::RowVectorXd distance =
          (normal.normalized().transpose() * (robot.colwise() - a)).cwiseAbs();
      Eigen::Index far = 0;
      const double farthest = distance.maxCoeff(&far);
      const auto at = std::find(chosen.begin(), chosen.end(), static_cast<std::size_t>(far));
      if (farthest <= distance(static_cast<Eigen::Index>(chosen[3]))) {
        // spread_points' fourth is as far off the plane as any: kept.
      } else if (at == chosen.end()) {
        chosen[3] = static_cast<std::size_t>(far);
      } else if (at - chosen.begin() > 3) {
        std::iter_swap(at, chosen.begin() + 3);
      }
    }
  }
  Points3 picked(3, static_cast<Eigen::Index>(chosen.size()));
  int n = 0;
  for (const std::size_t k : chosen) {
    picked.col(n) = robot.col(static_cast<Eigen::Index>(k));
    PlannedLocation m = plan.locations[fiducials[k]];
    m.point = "monitor-" + std::to_string(++n);
    m.role = Role::kMonitor;
    plan.locations.push_back(std::move(m));
  }
  MonitorChoice out;
  out.count = count;
  const auto [off, extent] = off_plane(picked);
  out.off_plane_rms_m = off;
  out.coplanar = count < 4 || !(off > 0.01 * extent);
  return out;
}

std::vector<ProgramLocation> monitor_program_locations(const PlanResult& plan, int visits) {
  VRREG_THROW_UNLESS(visits >= 1, "`monitor_visits` must be >= 1, got " << visits);
  std::vector<ProgramLocation> out;
  for (int v = 0; v < visits; ++v) {
    for (const PlannedLocation& l : plan.locations) {
      if (l.role != Role::kMonitor) continue;
      out.push_back({l.point, l.role, l.config.to_string(), l.q_rad, v, l.via_q_rad});
    }
  }
  return out;
}

ProgramDuration program_duration(const std::vector<ProgramLocation>& locations,
                                 const ProgramOptions& options, double reading_rate_hz) {
  options.validate();
  VRREG_THROW_UNLESS(std::isfinite(reading_rate_hz) && reading_rate_hz > 0.0,
                     "the tracker's reading rate must be > 0 Hz, got " << reading_rate_hz);
  ProgramDuration out;
  out.stops = static_cast<int>(locations.size());
  for (std::size_t k = 1; k < locations.size(); ++k) {
    const kinematics::JointVector& from = locations[k - 1].q_rad;
    const kinematics::JointVector& to = locations[k].q_rad;
    const kinematics::JointVector& via = locations[k].via_q_rad.value_or(to);
    VRREG_THROW_UNLESS(
        from.size() == to.size() && via.size() == to.size() && from.allFinite() &&
            to.allFinite() && via.allFinite(),
        "program duration: location '" << locations[k].point << "' has no finite joints");
    // A via point is a move of its own (without a stop): from -> via -> to.
    out.motion_s += move_time_s((via - from).cwiseAbs().maxCoeff(), options.joint_speed_rad_s,
                                options.joint_accel_rad_s2) +
                    move_time_s((to - via).cwiseAbs().maxCoeff(), options.joint_speed_rad_s,
                                options.joint_accel_rad_s2);
  }
  out.settle_s = out.stops * options.settle_s;
  out.readings_s = out.stops * options.repeats / reading_rate_hz;
  return out;
}

}  // namespace vrreg::planning
