// SPDX-License-Identifier: Apache-2.0
// Measuring a plan on a simulated test bed (`vrreg simulate --plan`): the robot takes the plan's
// joints, so a perfect robot and tracker read back exactly the plan's positions; labels, roles and
// config are kept; a plan for another tool or robot, or a broken plan, is refused.
#include "vrreg/simulation/plan_acquisition.hpp"

#include "simulation_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/ur_ik.hpp"
#include "vrreg_test.hpp"

namespace vrreg::simulation {
namespace {

// Three locations of the UR5 test bed reached with its controller's IK (nearest home).
std::vector<CommandedLocation> small_plan(const Testbed& testbed) {
  std::vector<CommandedLocation> plan;
  const std::vector<Eigen::Vector3d> points = {
      {0.45, 0.0, 0.25}, {0.47, 0.01, 0.24}, {0.44, -0.02, 0.27}};
  for (std::size_t k = 0; k < points.size(); ++k) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = testbed.tcp_rotation;
    pose.translation() = points[k];
    const kinematics::IkResult ik =
        kinematics::ur_inverse_kinematics_nearest(testbed.nominal, pose, testbed.home_q_rad);
    EXPECT_TRUE(ik.ok());
    CommandedLocation c;
    c.point = "P" + std::to_string(k);
    c.role = k == 1 ? Role::kTarget : Role::kFiducial;
    c.robot_m = points[k];
    c.config = 7;
    c.q_rad = ik.solutions.front().q_rad;
    plan.push_back(c);
  }
  return plan;
}

TEST(SimulatePlan, PerfectTestbedReadsThePlanExactlyInItsOrder) {
  const Testbed ur5 = ur5_testbed();
  const std::vector<CommandedLocation> plan = small_plan(ur5);
  const SimulatedDataset data = simulate_plan(ur5, plan, {4, testing::perfect_errors(ur5)});
  EXPECT_EQ(data.dataset, Dataset::kPlan);
  EXPECT_TRUE(data.has_config);
  ASSERT_EQ(data.visits.size(), 3u);
  ASSERT_EQ(data.readings.size(), 3u * 12u);  // K = 12 of the UR5 tracker
  const RigidTransform T_sensor_robot = data.T_robot_sensor.inverse();
  for (std::size_t v = 0; v < 3; ++v) {
    EXPECT_EQ(data.locations[v].point, plan[v].point);
    EXPECT_EQ(data.locations[v].role, plan[v].role);
    EXPECT_EQ(data.visits[v].config, 7);
    EXPECT_EIGEN_NEAR(data.visits[v].q_rad, plan[v].q_rad, 0.0);
    EXPECT_EIGEN_NEAR(data.visits[v].tcp_m, plan[v].robot_m, 1e-12);
  }
  for (const SimulatedReading& r : data.readings) {
    EXPECT_EIGEN_NEAR(r.sensor_m,
                      T_sensor_robot.apply(plan[static_cast<std::size_t>(r.visit)].robot_m), 1e-12);
  }
}

TEST(SimulatePlan, SameSeedSameReadingsAndTheDefaultRobotMissesByMillimetres) {
  const Testbed ur5 = ur5_testbed();
  const std::vector<CommandedLocation> plan = small_plan(ur5);
  const SimulatedDataset a = simulate_plan(ur5, plan, {9, {}});
  const SimulatedDataset b = simulate_plan(ur5, plan, {9, {}});
  ASSERT_EQ(a.readings.size(), b.readings.size());
  for (std::size_t k = 0; k < a.readings.size(); ++k) {
    EXPECT_EIGEN_NEAR(a.readings[k].sensor_m, b.readings[k].sensor_m, 0.0);
  }
  const double miss = (a.visits[0].tcp_m - plan[0].robot_m).norm();
  EXPECT_GT(miss, 1e-5);
  EXPECT_LT(miss, 1e-2);
}

TEST(SimulatePlan, RefusesPlansItCannotMeasure) {
  const Testbed ur5 = ur5_testbed();
  const std::vector<CommandedLocation> good = small_plan(ur5);
  EXPECT_THROW(simulate_plan(ur5, {}), InputError);
  std::vector<CommandedLocation> other_tool = good;
  other_tool[1].robot_m.z() += 0.06;  // planned for the flange, not the sphere
  EXPECT_THROW(simulate_plan(ur5, other_tool), InputError);
  std::vector<CommandedLocation> seven_joints = good;
  seven_joints[0].q_rad = Eigen::VectorXd::Zero(7);
  EXPECT_THROW(simulate_plan(ur5, seven_joints), InputError);
  std::vector<CommandedLocation> some_config = good;
  some_config[2].config.reset();
  EXPECT_THROW(simulate_plan(ur5, some_config), InputError);
  std::vector<CommandedLocation> twice = good;
  twice[2] = twice[0];
  EXPECT_THROW(simulate_plan(ur5, twice), InputError);
  EXPECT_THROW(plan_dataset(ur5, Dataset::kPlan), InputError);
  EXPECT_STREQ(to_string(Dataset::kPlan), "plan");
}

}  // namespace
}  // namespace vrreg::simulation
