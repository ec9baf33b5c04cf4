// SPDX-License-Identifier: Apache-2.0
// A simulated cell whose marker sits off the controller's tool: the tracker sees the
// real marker, the file keeps the controller's TCP, and without the option nothing changes.
#include "simulation_test_support.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/ur_ik.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"
#include "vrreg_test.hpp"

namespace vrreg::simulation {
namespace {

std::vector<CommandedLocation> two_locations(const Testbed& testbed) {
  std::vector<CommandedLocation> plan;
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0.45, 0.0, 0.25), Eigen::Vector3d(0.4, 0.1, 0.3)}) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = testbed.tcp_rotation;
    pose.translation() = p;
    const kinematics::IkResult ik =
        kinematics::ur_inverse_kinematics_nearest(testbed.nominal, pose, testbed.home_q_rad);
    EXPECT_TRUE(ik.ok());
    plan.push_back({"P" + std::to_string(plan.size()), Role::kFiducial, p, std::nullopt,
                    ik.solutions.front().q_rad});
  }
  return plan;
}

TEST(SimulatedMarkerOffset, TrackerSeesTheRealMarkerAndTheFileKeepsTheTcp) {
  const Testbed ur5 = ur5_testbed();
  const std::vector<CommandedLocation> plan = two_locations(ur5);
  SimulationOptions options{4, testing::perfect_errors(ur5)};
  options.marker_flange_m = kRealisticMarkerFlangeM;
  const SimulatedDataset data = simulate_plan(ur5, plan, options);
  ASSERT_TRUE(data.marker_flange_m.has_value());
  const RigidTransform T_sensor_robot = data.T_robot_sensor.inverse();
  const kinematics::SerialChain flange = ur5.nominal.with_tool(Eigen::Isometry3d::Identity());
  for (std::size_t v = 0; v < plan.size(); ++v) {
    const Eigen::Vector3d marker =
        kinematics::forward_kinematics(flange, plan[v].q_rad) * kRealisticMarkerFlangeM;
    EXPECT_EIGEN_NEAR(data.readings[12 * v].sensor_m, T_sensor_robot.apply(marker), 1e-12);
    EXPECT_EIGEN_NEAR(data.locations[v].robot_m, plan[v].robot_m, 0.0);
  }
}

TEST(SimulatedMarkerOffset, TheToolsOwnOffsetGivesTheSameBytesAsNone) {
  const Testbed ur5 = ur5_testbed();
  const std::vector<CommandedLocation> plan = two_locations(ur5);
  SimulationOptions with{9, std::nullopt};
  with.marker_flange_m = ur5.nominal.T_flange_tcp().translation();
  const SimulatedDataset a = simulate_plan(ur5, plan, {9, std::nullopt});
  const SimulatedDataset b = simulate_plan(ur5, plan, with);
  ASSERT_EQ(a.readings.size(), b.readings.size());
  for (std::size_t r = 0; r < a.readings.size(); ++r) {
    EXPECT_EIGEN_NEAR(a.readings[r].sensor_m, b.readings[r].sensor_m, 0.0);
  }
}

}  // namespace
}  // namespace vrreg::simulation
