// SPDX-License-Identifier: Apache-2.0
// Time in a simulated cell: a bump of the stated size, link growth that moves the TCP by the
// stated RMS, the warm-up curve, and monitor visits with fresh repeatability each.
#include "vrreg/simulation/cell_events.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "simulation_test_support.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"
#include "vrreg/simulation/read_locations.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg_test.hpp"

namespace vrreg::simulation {
namespace {

TEST(CellEvents, ABumpHasTheStatedSize) {
  Random rng(4);
  Points3 cell(3, 50);
  for (Eigen::Index k = 0; k < 50; ++k) cell.col(k) = Eigen::Vector3d(0, 0, 2.1) + rng.normal3(0.1);
  for (const double size : {1e-4, 5e-4}) {
    const RigidTransform T = draw_bump(cell, size, rng);
    const double rms = std::sqrt((T.apply_all(cell) - cell).colwise().squaredNorm().mean());
    EXPECT_NEAR(rms, size, 1e-9 * size);
    EXPECT_NEAR(T.rotation.determinant(), 1.0, 1e-14);
  }
  // A test bed's bump is the seed's: the same at every time, another for another seed.
  const Testbed bed = ur5_testbed();
  const RigidTransform T = tracker_pose(bed.default_errors.tracker, bed.volume_centre_m);
  const RigidTransform a = testbed_bump(bed, T, 1e-4, 7);
  EXPECT_EQ(a.translation_m, testbed_bump(bed, T, 1e-4, 7).translation_m);
  EXPECT_NE(a.translation_m, testbed_bump(bed, T, 1e-4, 8).translation_m);
}

TEST(CellEvents, APlanReadLaterSeesTheBumpAndTheWarmUp) {
  const Testbed bed = ur5_testbed();
  const kinematics::JointVector q = bed.home_q_rad;
  const Eigen::Vector3d tcp = kinematics::forward_kinematics(bed.nominal, q).translation();
  const std::vector<CommandedLocation> plan{{"m1", Role::kMonitor, tcp, std::nullopt, q}};
  SimulationOptions now;
  now.seed = 4;
  now.monitor_visits = 5;
  const SimulatedDataset before = simulate_plan(bed, plan, now);
  ASSERT_EQ(before.visits.size(), 5u);
  EXPECT_EQ(before.visits[3].round, 3);
  SimulationOptions later = now;
  later.time_s = 7200;
  later.events.bump_time_s = 3600;
  later.events.bump_rms_m = 2e-4;
  const SimulatedDataset after = simulate_plan(bed, plan, later);
  const RigidTransform bump = testbed_bump(bed, before.T_robot_sensor, 2e-4, now.seed);
  EXPECT_EIGEN_NEAR(after.T_robot_sensor.rotation,
                    before.T_robot_sensor.rotation * bump.rotation.transpose(), 1e-15);
  // Later readings draw new noise; time 0 draws what it always did.
  EXPECT_NE(after.readings[0].sensor_m, before.readings[0].sensor_m);
  EXPECT_EQ(simulate_plan(bed, plan, now).readings[0].sensor_m, before.readings[0].sensor_m);
  later.events.bump_rms_m = 0.0;
  // Grown links move the tool: 5 visits' mean (0.05 mm repeatability each) by far more than it.
  later.events.thermal.warmup_growth = 2e-3;
  const SimulatedDataset warm = simulate_plan(bed, plan, later);
  Eigen::Vector3d moved = Eigen::Vector3d::Zero();
  for (std::size_t v = 0; v < 5; ++v) moved += (warm.visits[v].tcp_m - before.visits[v].tcp_m) / 5;
  EXPECT_GT(moved.norm(), 0.5e-3);
  EXPECT_EQ(warm.time_s, 7200);
}

TEST(CellEvents, GrowthMovesTheToolByTheStatedRms) {
  const Testbed bed = ur5_testbed();
  Random rng(2);
  const RobotErrors errors = draw_robot_errors(bed.default_errors.robot, 6, rng);
  const SimulatedRobot robot(bed.nominal, bed.default_errors.robot, errors);
  Eigen::MatrixXd q(6, 20);
  for (Eigen::Index k = 0; k < 20; ++k)
    q.col(k) = bed.home_q_rad + 0.2 * rng.normal3(1.0).replicate(2, 1);
  const double g = growth_for_displacement(robot, q, 2e-4);
  const SimulatedRobot warm = grown(robot, g);
  double ss = 0.0;
  for (Eigen::Index k = 0; k < 20; ++k)
    ss += (warm.actual_tcp_m(q.col(k)) - robot.actual_tcp_m(q.col(k))).squaredNorm();
  EXPECT_NEAR(std::sqrt(ss / 20), 2e-4, 2e-4 * 1e-3);  // linear in the growth to 1e-3
  EXPECT_GT(g, 0.0);
  ThermalModel thermal;
  thermal.warmup_growth = 2e-4;
  EXPECT_EQ(thermal.growth_at(0), 0.0);
  EXPECT_NEAR(thermal.growth_at(thermal.warmup_time_constant_s), 2e-4 * (1 - std::exp(-1.0)),
              1e-18);
  thermal.daily_growth = 1e-5;
  EXPECT_NEAR(thermal.growth_at(1e9), 2e-4 + 1e-5 * std::sin(2 * M_PI * 1e9 / 86400), 1e-12);
}

TEST(CellEvents, EachVisitDrawsItsOwnRepeatability) {
  const Testbed bed = ur5_testbed();
  Random rng(6);
  const RobotErrors errors = draw_robot_errors(bed.default_errors.robot, 6, rng);
  const SimulatedRobot robot(bed.nominal, bed.default_errors.robot, errors);
  const RigidTransform T = tracker_pose(bed.default_errors.tracker, bed.volume_centre_m);
  const std::vector<CommandedLocation> where{
      {"m", Role::kMonitor, Eigen::Vector3d::Zero(), std::nullopt, bed.home_q_rad}};
  const std::vector<Location> visits =
      read_locations(robot, T, bed.default_errors.tracker, where, 400, rng);
  ASSERT_EQ(visits.size(), 400u);
  EXPECT_EQ(visits[7].visit, 7);
  EXPECT_EQ(visits[7].n_readings, bed.default_errors.tracker.readings_per_location);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Location& v : visits) mean += v.sensor_m / 400.0;
  double ss = 0.0;
  for (const Location& v : visits) ss += (v.sensor_m - mean).squaredNorm();
  // Per axis: repeatability^2 + tracker^2 / K (0.05 and 0.058 / sqrt 12 mm).
  const double expected = std::sqrt(std::pow(0.05e-3, 2) + std::pow(0.058e-3, 2) / 12);
  EXPECT_NEAR(std::sqrt(ss / (3 * 399)), expected, 0.1 * expected);
}

}  // namespace
}  // namespace vrreg::simulation
