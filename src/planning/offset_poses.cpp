// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/offset_poses.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>

#include "vrreg/core/check.hpp"

namespace vrreg::planning {
namespace {

std::size_t nearest_location(const PlanResult& plan, const Eigen::Vector3d& p) {
  std::size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < plan.locations.size(); ++k) {
    const double d = (plan.locations[k].robot_m - p).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = k;
    }
  }
  return best;
}

int nearest_part(const PlanResult& plan, const Eigen::Vector3d& p) {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < plan.parts.size(); ++i) {
    const double d = (plan.parts[i].robot_m - p).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace

std::vector<Eigen::Matrix3d> offset_tilts(double tilt_rad) {
  const auto about = [](double angle, const Eigen::Vector3d& axis) {
    return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
  };
  return {about(tilt_rad, Eigen::Vector3d::UnitX()), about(tilt_rad, Eigen::Vector3d::UnitY()),
          about(-tilt_rad, Eigen::Vector3d::UnitX()), about(-tilt_rad, Eigen::Vector3d::UnitY())};
}

OffsetPoseSummary add_offset_poses(const kinematics::SerialChain& chain, PlanResult& plan,
                                   const ArmConfigurationOptions& arm, double tilt_rad) {
  VRREG_THROW_UNLESS(
      std::isfinite(tilt_rad) && tilt_rad > 0.0 && tilt_rad <= std::numbers::pi / 3.0,
      "the offset tilt must be in (0, 60] deg, got " << tilt_rad << " rad");
  VRREG_THROW_UNLESS(!plan.locations.empty(), "offset poses: the plan has no locations");
  Eigen::Vector3d lo = plan.locations.front().robot_m;
  Eigen::Vector3d hi = lo;
  for (const PlannedLocation& l : plan.locations) {
    lo = lo.cwiseMin(l.robot_m);
    hi = hi.cwiseMax(l.robot_m);
  }
  std::vector<Eigen::Vector3d> positions;
  for (int corner = 0; corner < 8; ++corner) {
    positions.emplace_back((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                           (corner & 4) ? hi.z() : lo.z());
  }
  positions.push_back(0.5 * (lo + hi));

  const std::vector<Eigen::Matrix3d> tilts = offset_tilts(tilt_rad);
  OffsetPoseSummary out;
  out.tilt_rad = tilt_rad;
  std::vector<PlannedLocation> added;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const PlannedLocation& reference = plan.locations[nearest_location(plan, positions[i])];
    for (std::size_t t = 0; t < tilts.size(); ++t) {
      ArmConfigurationOptions tilted = arm;
      tilted.R_base_tcp = arm.R_base_tcp * tilts[t];  // about the TCP's own axes
      const JointChoice choice = nearest_joints(chain, positions[i], reference.q_rad, tilted);
      if (!choice.ok()) {
        ++out.n_unreachable;
        continue;
      }
      PlannedLocation l;
      l.point = std::string(kOffsetPosePrefix) + std::to_string(i) + "-" + std::to_string(t);
      l.role = Role::kFiducial;
      l.part = nearest_part(plan, positions[i]);
      l.grid_index = Eigen::Vector3i::Constant(-2);  // no grid node (-1 is the target)
      l.robot_m = positions[i];
      l.q_rad = choice.q_rad;
      l.config = choice.config;
      l.joint_distance_rad = choice.distance_rad;
      added.push_back(std::move(l));
    }
  }
  out.n_added = static_cast<long long>(added.size());
  plan.locations.insert(plan.locations.begin(), added.begin(), added.end());
  return out;
}

}  // namespace vrreg::planning
