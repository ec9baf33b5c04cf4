// SPDX-License-Identifier: Apache-2.0
// The robot error model (DH errors, transmission error, repeatability, gravity compliance) and the
// tracker model.
#include <cmath>
#include <numbers>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/simulation/gravity_compliance.hpp"
#include "vrreg/simulation/simulated_robot.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/simulation/tracker_model.hpp"
#include "vrreg_test.hpp"

namespace vrreg::simulation {
namespace {

using units::kPi;

kinematics::JointVector some_joints() {
  kinematics::JointVector q(6);
  q << 0.3, -1.2, 1.5, -1.9, -1.57, 0.4;
  return q;
}

TEST(RobotErrorModel, DrawsOneRobotPerSeedWithTheGivenSpread) {
  RobotErrorModel model;
  model.joint_offset_sigma_rad = 1e-2;
  model.link_length_sigma_m = 2e-3;
  model.transmission_amplitude_rad = std::vector<double>(6, 1e-4);
  model.transmission_period_rad = std::vector<double>(6, 0.3);
  Random rng(5);
  double sum_sq_theta = 0.0, sum_sq_a = 0.0;
  const int n_robots = 2000;
  for (int k = 0; k < n_robots; ++k) {
    const RobotErrors e = draw_robot_errors(model, 6, rng);
    ASSERT_EQ(e.dh_delta.size(), 6u);
    ASSERT_EQ(e.transmission_phase_rad.size(), 6u);
    for (const auto& d : e.dh_delta) {
      sum_sq_theta += d.theta_offset_rad * d.theta_offset_rad;
      sum_sq_a += d.a_m * d.a_m;
      EXPECT_EQ(d.d_m, 0.0);
      EXPECT_EQ(d.alpha_rad, 0.0);
    }
    for (double phase : e.transmission_phase_rad) {
      EXPECT_GE(phase, 0.0);
      EXPECT_LT(phase, 2 * kPi);
    }
  }
  EXPECT_NEAR(std::sqrt(sum_sq_theta / (6 * n_robots)), 1e-2, 3e-4);
  EXPECT_NEAR(std::sqrt(sum_sq_a / (6 * n_robots)), 2e-3, 6e-5);
}

TEST(RobotErrorModel, ValidateRejectsBadValues) {
  RobotErrorModel model;
  EXPECT_NO_THROW(model.validate(6));
  model.repeatability_sigma_m = -1.0;
  EXPECT_THROW(model.validate(6), InputError);
  model = {};
  model.transmission_amplitude_rad = {1e-4};
  EXPECT_THROW(model.validate(6), InputError);  // one per joint
  model.transmission_amplitude_rad = std::vector<double>(6, 1e-4);
  model.transmission_period_rad = std::vector<double>(6, 0.0);
  EXPECT_THROW(model.validate(6), InputError);  // period must be > 0
  model = {};
  model.compliance = true;
  EXPECT_THROW(model.validate(6), InputError);  // masses and stiffness needed
  EXPECT_TRUE(RobotErrorModel{}.is_perfect());
  EXPECT_FALSE(ur5_testbed().default_errors.robot.is_perfect());
  EXPECT_NO_THROW(ur5_testbed().default_errors.validate(6));
  EXPECT_NO_THROW(lwr4_testbed().default_errors.validate(7));
}

TEST(SimulatedRobot, PerfectRobotIsTheNominalOne) {
  const kinematics::SerialChain chain = kinematics::ur5();
  RobotErrorModel model;
  Random rng(1);
  const SimulatedRobot robot(chain, model, draw_robot_errors(model, 6, rng));
  const kinematics::JointVector q = some_joints();
  EXPECT_EIGEN_NEAR(robot.actual_joints(q), q, 0.0);
  EXPECT_EIGEN_NEAR(robot.actual_tcp_m(q), kinematics::forward_kinematics(chain, q).translation(),
                    0.0);
}

TEST(SimulatedRobot, TransmissionErrorIsASinusoidOfTheCommandedAngle) {
  const kinematics::SerialChain chain = kinematics::ur5();
  RobotErrorModel model;
  model.transmission_amplitude_rad = {1e-3, 0, 0, 0, 0, 2e-3};
  model.transmission_period_rad = {0.5, 1, 1, 1, 1, 0.25};
  RobotErrors errors;
  errors.dh_delta.resize(6);
  errors.transmission_phase_rad = {0.1, 0, 0, 0, 0, 2.0};
  const SimulatedRobot robot(chain, model, errors);
  const kinematics::JointVector q = some_joints();
  kinematics::JointVector expected = q;
  expected(0) += 1e-3 * std::sin(2 * kPi * q(0) / 0.5 + 0.1);
  expected(5) += 2e-3 * std::sin(2 * kPi * q(5) / 0.25 + 2.0);
  EXPECT_EIGEN_NEAR(robot.actual_joints(q), expected, 1e-15);
  // Periodic: one period later, the same error.
  kinematics::JointVector q2 = q;
  q2(0) += 0.5;
  EXPECT_NEAR(robot.actual_joints(q2)(0) - q2(0), expected(0) - q(0), 1e-15);
}

TEST(SimulatedRobot, DhErrorsMoveTheTcpAndRepeatabilityScatters) {
  const kinematics::SerialChain chain = kinematics::ur5();
  RobotErrorModel model;
  model.repeatability_sigma_m = 1e-4;
  RobotErrors errors;
  errors.dh_delta.resize(6);
  errors.dh_delta[1].theta_offset_rad = 1e-3;  // shoulder: TCP moves ~ 1 mrad x reach
  const SimulatedRobot robot(chain, model, errors);
  const kinematics::JointVector q = some_joints();
  const Eigen::Vector3d nominal = kinematics::forward_kinematics(chain, q).translation();
  const double moved = (robot.actual_tcp_m(q) - nominal).norm();
  EXPECT_GT(moved, 2e-4);
  EXPECT_LT(moved, 1e-3);
  Random rng(3);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const int n = 4000;
  double sum_sq = 0.0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d d = robot.visit_tcp_m(q, rng) - robot.actual_tcp_m(q);
    sum += d;
    sum_sq += d.squaredNorm();
  }
  EXPECT_NEAR(std::sqrt(sum_sq / (3 * n)), 1e-4, 4e-6);
  EXPECT_LT((sum / n).norm(), 1e-5);
}

TEST(GravityCompliance, VerticalArmFeelsNoTorqueAndALeverArmSags) {
  const kinematics::SerialChain lwr = kinematics::lwr4();
  const std::vector<double> masses(7, 2.0);
  const kinematics::JointVector candle = kinematics::JointVector::Zero(7);
  EXPECT_LT(gravity_torques_nm(lwr, candle, masses, 1.0).cwiseAbs().maxCoeff(), 1e-12);
  // Joint 2 at 90 deg: the arm sticks out horizontally; the torque about joint 2 is the weight
  // of everything beyond it times its lever (links at 0.2, 0.5, 0.69, 0.78 m ...).
  kinematics::JointVector q = candle;
  q(1) = kPi / 2;
  const kinematics::JointVector tau = gravity_torques_nm(lwr, q, masses, 0.0);
  EXPECT_GT(std::abs(tau(1)), 10.0);
  // Compliance makes the TCP sag (z decreases).
  RobotErrorModel model;
  model.compliance = true;
  model.link_mass_kg = masses;
  model.joint_stiffness_nm_per_rad = std::vector<double>(7, 1e4);
  RobotErrors errors;
  errors.dh_delta.resize(7);
  const SimulatedRobot robot(lwr, model, errors);
  const double sag =
      robot.actual_tcp_m(q).z() - kinematics::forward_kinematics(lwr, q).translation().z();
  EXPECT_LT(sag, -1e-4);
}

TEST(TrackerModel, LooksAtTheVolumeCentreFromItsDistance) {
  TrackerModel model;
  model.distance_m = 1.8;
  model.azimuth_rad = 0.7;
  model.elevation_rad = 0.4;
  const Eigen::Vector3d centre(0.5, 0.25, 0.3);
  const RigidTransform T_robot_sensor = tracker_pose(model, centre);
  EXPECT_NEAR((T_robot_sensor.translation_m - centre).norm(), 1.8, 1e-12);
  EXPECT_NEAR(T_robot_sensor.rotation.determinant(), 1.0, 1e-12);
  EXPECT_EIGEN_NEAR(T_robot_sensor.inverse().apply(centre), Eigen::Vector3d(0, 0, 1.8), 1e-12);
  EXPECT_NEAR(T_robot_sensor.rotation.col(0).z(), 0.0, 1e-12);  // sensor x horizontal
  model.readings_per_location = 0;
  EXPECT_THROW(model.validate(), InputError);
  model.readings_per_location = 1;
  model.elevation_rad = kPi / 2;
  EXPECT_THROW(model.validate(), InputError);
}

}  // namespace
}  // namespace vrreg::simulation
