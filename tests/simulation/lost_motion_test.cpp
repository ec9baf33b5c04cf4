// SPDX-License-Identifier: Apache-2.0
// Lost motion of the simulated robots: each joint stops short of its command against the
// direction of its last move, and the acquisition follows the visiting order to know it.
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/simulated_robot.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg_test.hpp"

namespace vrreg::simulation {
namespace {

constexpr double kArcmin = units::kPi / (180.0 * 60.0);

RobotErrorModel lost_motion_only(double take_up) {
  RobotErrorModel model;
  model.lost_motion_rad = {0.8 * kArcmin, 0.2 * kArcmin, 0.15 * kArcmin,
                           0.6 * kArcmin, 0.5 * kArcmin, 0.4 * kArcmin};
  model.lost_motion_take_up = take_up;
  return model;
}

TEST(LostMotion, OppositeApproachesDifferByTheJacobianTimesTheLostMotion) {
  const kinematics::SerialChain chain = kinematics::ur5();
  const RobotErrorModel model = lost_motion_only(0.75);
  Random rng(3);
  const SimulatedRobot robot(chain, model, draw_robot_errors(model, 6, rng));
  kinematics::JointVector q(6);
  q << 0.3, -1.2, 1.5, -1.9, -1.57, 0.4;
  const kinematics::JointVector below = q.array() - 0.1;  // every joint arrives moving up
  const kinematics::JointVector above = q.array() + 0.1;  // ... moving down
  JointApproach up(below), down(above);
  const kinematics::JointVector sign_up = up.move_to(q);
  const kinematics::JointVector sign_down = down.move_to(q);
  EXPECT_EIGEN_NEAR(sign_up, kinematics::JointVector::Ones(6), 0.0);
  EXPECT_EIGEN_NEAR(sign_down, -kinematics::JointVector::Ones(6), 0.0);

  const Eigen::Map<const Eigen::VectorXd> b(model.lost_motion_rad.data(), 6);
  const Eigen::VectorXd lag_rad = model.lost_motion_take_up * b;  // down minus up, per joint
  EXPECT_EIGEN_NEAR(robot.actual_joints(q, sign_down) - robot.actual_joints(q, sign_up), lag_rad,
                    1e-15);  // the rounding of angles near 2
  // The two arrivals sit symmetrically about q: their difference is J(q) * lag up to third order
  // in the lag (below 1e-12 m at these sizes).
  const Eigen::Vector3d expected_m = kinematics::jacobian(chain, q).topRows<3>() * lag_rad;
  const Eigen::Vector3d moved_m = robot.actual_tcp_m(q, sign_down) - robot.actual_tcp_m(q, sign_up);
  EXPECT_GT(expected_m.norm(), 5e-5);  // a lost motion of tens of micrometres at the TCP
  EXPECT_EIGEN_NEAR(moved_m, expected_m, 1e-12);
  // Without approach signs (or before any move) the joints are as commanded.
  EXPECT_EIGEN_NEAR(robot.actual_joints(q), q, 0.0);
  EXPECT_EIGEN_NEAR(robot.actual_joints(q, JointApproach(q).sign()), q, 0.0);
}

TEST(LostMotion, AJointThatDoesNotMoveKeepsItsSide) {
  kinematics::JointVector start(3), a(3), b(3);
  start << 0.0, 0.0, 0.0;
  a << 0.1, -0.1, 0.0;
  b << 0.1, 0.2, 0.0;
  JointApproach approach(start);
  EXPECT_EIGEN_NEAR(approach.move_to(a), Eigen::Vector3d(1, -1, 0), 0.0);
  EXPECT_EIGEN_NEAR(approach.move_to(b), Eigen::Vector3d(1, 1, 0), 0.0);
  EXPECT_EIGEN_NEAR(approach.move_to(b), Eigen::Vector3d(1, 1, 0), 0.0);  // a repeat
}

TEST(LostMotion, ValidateRejectsBadValues) {
  RobotErrorModel model = lost_motion_only(1.0);
  EXPECT_NO_THROW(model.validate(6));
  EXPECT_FALSE(model.is_perfect());
  model.lost_motion_take_up = 0.0;
  EXPECT_TRUE(model.is_perfect());
  model.lost_motion_take_up = 1.5;
  EXPECT_THROW(model.validate(6), InputError);
  model = lost_motion_only(1.0);
  model.lost_motion_rad[2] = -1e-4;
  EXPECT_THROW(model.validate(6), InputError);
  model.lost_motion_rad = {1e-4};
  EXPECT_THROW(model.validate(6), InputError);  // one per joint
}

// The acquisition follows the visiting order from home: each visit of a lost-motion UR5 lands
// where the robot without it lands, moved by the closed form at the path's signs; the robot and
// every noise draw stay those of the seed.
TEST(LostMotion, AcquisitionFollowsTheVisitingOrder) {
  const Testbed testbed = ur5_testbed();
  SimulationOptions plain;
  plain.seed = 4;
  plain.errors = testbed.default_errors;
  SimulationOptions with = plain;
  with.errors->robot.lost_motion_rad = lost_motion_only(1.0).lost_motion_rad;
  const SimulatedDataset a = simulate_dataset(testbed, Dataset::kA1, plain);
  const SimulatedDataset b = simulate_dataset(testbed, Dataset::kA1, with);
  ASSERT_EQ(a.visits.size(), b.visits.size());
  ASSERT_GT(a.visits.size(), 100u);
  const SimulatedRobot robot(testbed.nominal, with.errors->robot, b.robot);
  JointApproach approach(testbed.home_q_rad);
  double max_shift_m = 0.0;
  for (std::size_t v = 0; v < a.visits.size(); ++v) {
    const kinematics::JointVector& q = a.visits[v].q_rad;
    const kinematics::JointVector& sign = approach.move_to(q);
    const Eigen::Vector3d shift_m = robot.actual_tcp_m(q, sign) - robot.actual_tcp_m(q);
    EXPECT_EIGEN_NEAR(b.visits[v].tcp_m - a.visits[v].tcp_m, shift_m, 1e-15);
    max_shift_m = std::max(max_shift_m, shift_m.norm());
  }
  EXPECT_GT(max_shift_m, 2e-5);
  // Without lost motion nothing changed: empty and all-zero lists give the same readings.
  SimulationOptions zero = plain;
  zero.errors->robot.lost_motion_rad.assign(6, 0.0);
  const SimulatedDataset c = simulate_dataset(testbed, Dataset::kA1, zero);
  ASSERT_EQ(a.readings.size(), c.readings.size());
  for (std::size_t r = 0; r < a.readings.size(); ++r) {
    ASSERT_EQ(a.readings[r].sensor_m, c.readings[r].sensor_m);
  }
}

}  // namespace
}  // namespace vrreg::simulation
