// SPDX-License-Identifier: Apache-2.0
// Monitor points of a plan: four of them off one plane when the fiducials allow (three always lie
// on one), said when they do not; and how long the check program takes on the robot, against
// movej's trapezoidal profile worked by hand.
#include "vrreg/planning/monitor_points.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg::planning::monitor_points_test {
namespace {

// Fiducials on an n x n x layers grid of 50 mm (z the layers), each with joints.
PlanResult grid_plan(int n, int layers) {
  PlanResult plan;
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        PlannedLocation l;
        l.point = "F" + std::to_string(i) + std::to_string(j) + std::to_string(k);
        l.role = Role::kFiducial;
        l.robot_m = Eigen::Vector3d(-0.4 + 0.05 * i, -0.1 + 0.05 * j, 0.3 + 0.05 * k);
        l.q_rad = kinematics::JointVector::Constant(6, 0.1 * (i + j + k));
        plan.locations.push_back(l);
      }
  return plan;
}

Points3 monitors_of(const PlanResult& plan) {
  std::vector<Eigen::Vector3d> points;
  for (const PlannedLocation& l : plan.locations)
    if (l.role == Role::kMonitor) points.push_back(l.robot_m);
  Points3 out(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) out.col(static_cast<Eigen::Index>(k)) = points[k];
  return out;
}

// Distance of the 4th point from the plane of the first three [m].
double fourth_off_plane(const Points3& p) {
  const Eigen::Vector3d n = (p.col(1) - p.col(0)).cross(p.col(2) - p.col(0)).normalized();
  return std::abs(n.dot(p.col(3) - p.col(0)));
}

TEST(MonitorPoints, FourAreOffOnePlaneWhenTheFiducialsAllow) {
  for (const int layers : {2, 6}) {
    PlanResult plan = grid_plan(6, layers);
    const MonitorChoice four = add_monitor_points(plan, kDefaultMonitorPoints);
    EXPECT_FALSE(four.coplanar);
    const Points3 m = monitors_of(plan);
    ASSERT_EQ(m.cols(), 4);
    EXPECT_GT(fourth_off_plane(m), 0.02) << "layers " << layers;
  }
  PlanResult three = grid_plan(6, 6);
  EXPECT_TRUE(add_monitor_points(three, 3).coplanar);
  PlanResult flat = grid_plan(6, 1);
  const MonitorChoice on_plane = add_monitor_points(flat, 4);
  EXPECT_TRUE(on_plane.coplanar);
  EXPECT_LT(on_plane.off_plane_rms_m, 1e-12);
  PlanResult small = grid_plan(1, 2);
  EXPECT_THROW(add_monitor_points(small, 4), InputError);
}

TEST(MonitorPoints, TheCheckTakesMovesSettlingAndReadings) {
  ProgramOptions o;  // movej v 0.5 rad/s, a 0.8 rad/s^2, settle 1 s, 12 readings
  std::vector<ProgramLocation> path(3);
  for (ProgramLocation& l : path) l.q_rad = kinematics::JointVector::Zero(6);
  path[1].q_rad(1) = 1.0;   // long: cruise at v, 1 / 0.5 + 0.5 / 0.8 = 2.625 s
  path[1].q_rad(4) = -0.4;  // not the farthest joint
  path[2].q_rad = path[1].q_rad;
  path[2].q_rad(1) += 0.1;  // short: v never reached, 2 sqrt(0.1 / 0.8) s
  const ProgramDuration d = program_duration(path, o, 120.0);
  EXPECT_EQ(d.stops, 3);
  EXPECT_NEAR(d.motion_s, 2.625 + 2.0 * std::sqrt(0.1 / 0.8), 1e-12);
  EXPECT_DOUBLE_EQ(d.settle_s, 3.0);
  EXPECT_DOUBLE_EQ(d.readings_s, 3 * 12 / 120.0);
  EXPECT_DOUBLE_EQ(d.total_s(), d.motion_s + d.settle_s + d.readings_s);
  // The plan's check program: 4 points in 12 rounds.
  PlanResult plan = grid_plan(6, 6);
  add_monitor_points(plan, 4);
  const std::vector<ProgramLocation> check = monitor_program_locations(plan, 12);
  EXPECT_EQ(program_duration(check, o).stops, 48);
  EXPECT_THROW(program_duration(path, o, 0.0), InputError);
}

}  // namespace
}  // namespace vrreg::planning::monitor_points_test
