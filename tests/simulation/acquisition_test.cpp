// SPDX-License-Identifier: Apache-2.0
// Acquisition of the paper's datasets: counts, exact rigidity without errors, determinism,
// controller behaviour (UR nearest solution, LWR four configurations) and noise levels.
#include "vrreg/simulation/acquisition.hpp"

#include <cmath>
#include <set>

#include "simulation_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/ur_ik.hpp"
#include "vrreg/simulation/simulated_robot.hpp"
#include "vrreg_test.hpp"

namespace vrreg::simulation {
namespace {

using testing::perfect_errors;

struct Counts {
  std::size_t fiducials = 0, targets = 0;
};

Counts count_roles(const std::vector<PlannedLocation>& plan) {
  Counts c;
  for (const auto& l : plan) (l.role == Role::kTarget ? c.targets : c.fiducials)++;
  return c;
}

TEST(DatasetPlan, HasThePapersCounts) {
  const Testbed ur5 = ur5_testbed();
  const Counts a1 = count_roles(plan_dataset(ur5, Dataset::kA1));
  EXPECT_EQ(a1.fiducials, 1167u);
  EXPECT_EQ(a1.targets, 120u);
  const Counts a2 = count_roles(plan_dataset(ur5, Dataset::kA2));
  EXPECT_EQ(a2.fiducials, 7965u);
  EXPECT_EQ(a2.targets, 960u);
  const std::vector<PlannedLocation> b = plan_dataset(ur5, Dataset::kB);
  EXPECT_EQ(b.size(), 9720u);
  EXPECT_EQ(count_roles(b).targets, 120u);
  std::set<std::string> labels;
  for (const auto& l : b) labels.insert(l.point);
  EXPECT_EQ(labels.size(), b.size()) << "labels must be unique";
  const Counts grid = count_roles(plan_dataset(lwr4_testbed(), Dataset::kGrid));
  EXPECT_EQ(grid.fiducials, 1423u);
  EXPECT_EQ(grid.targets, 150u);
}

TEST(DatasetPlan, BSurroundsEachA1TargetWithTenCubes) {
  const std::vector<PlannedLocation> b = plan_dataset(ur5_testbed(), Dataset::kB);
  std::vector<Eigen::Vector3d> a1_targets;
  for (const auto& l : plan_dataset(ur5_testbed(), Dataset::kA1)) {
    if (l.role == Role::kTarget) a1_targets.push_back(l.robot_m);
  }
  int n_targets = 0;
  for (const auto& l : b) {
    if (l.role == Role::kTarget) {
      ++n_targets;
      bool in_a1 = false;
      for (const auto& t : a1_targets) in_a1 = in_a1 || (t - l.robot_m).norm() < 1e-12;
      EXPECT_TRUE(in_a1) << l.point;
      continue;
    }
    const PlannedLocation& owner = b[static_cast<std::size_t>(l.owner)];
    ASSERT_EQ(owner.role, Role::kTarget);
    const Eigen::Vector3d offset = (l.robot_m - owner.robot_m).cwiseAbs();
    EXPECT_EIGEN_NEAR(offset, Eigen::Vector3d::Constant(0.5 * l.cube_edge_m), 1e-12);
  }
  EXPECT_EQ(n_targets, 120);
}

TEST(DatasetPlan, RejectsDatasetsOfTheOtherTestbed) {
  EXPECT_THROW(plan_dataset(ur5_testbed(), Dataset::kGrid), InputError);
  EXPECT_THROW(plan_dataset(lwr4_testbed(), Dataset::kA1), InputError);
  EXPECT_THROW(parse_dataset("A3"), InputError);
  EXPECT_EQ(parse_dataset("a2"), Dataset::kA2);
  EXPECT_THROW(testbed_by_name("ur10"), InputError);
}

TEST(Acquisition, PerfectRobotAndTrackerGiveExactlyRigidData) {
  const Testbed testbed = ur5_testbed();
  const SimulatedDataset data =
      simulate_dataset(testbed, Dataset::kA1, {7, perfect_errors(testbed)});
  const RigidTransform T_sensor_robot = data.T_robot_sensor.inverse();
  for (const SimulatedReading& r : data.readings) {
    const auto& loc = data.locations[static_cast<std::size_t>(data.visits[r.visit].location)];
    ASSERT_EIGEN_NEAR(r.sensor_m, T_sensor_robot.apply(loc.robot_m), 1e-12);
  }
  // Rigid-body condition (Eq. 1) over all pairs of fiducial visits: sigma_L <= 1e-9 mm.
  const Points3 sensor = visit_means_m(data);
  double worst = 0.0;
  for (Eigen::Index i = 0; i < sensor.cols(); ++i) {
    const Eigen::Vector3d& yi = data.locations[static_cast<std::size_t>(i)].robot_m;
    for (Eigen::Index j = i + 1; j < sensor.cols(); ++j) {
      const Eigen::Vector3d& yj = data.locations[static_cast<std::size_t>(j)].robot_m;
      worst = std::max(worst, std::abs((sensor.col(i) - sensor.col(j)).norm() - (yi - yj).norm()));
    }
  }
  EXPECT_LE(worst, 1e-12);  // m, i.e. 1e-9 mm
}

TEST(Acquisition, ReadingsPerVisitAndVisitingOrder) {
  const Testbed testbed = ur5_testbed();
  const SimulatedDataset data = simulate_dataset(testbed, Dataset::kA1, {});
  ASSERT_EQ(data.visits.size(), 1287u);
  ASSERT_EQ(data.readings.size(), 1287u * 12u);
  for (std::size_t k = 0; k < data.readings.size(); ++k) {
    EXPECT_EQ(data.readings[k].visit, static_cast<int>(k / 12));
    EXPECT_EQ(data.readings[k].repeat, static_cast<int>(k % 12));
  }
}

TEST(Acquisition, SameSeedSameDataOtherSeedOtherRobot) {
  const Testbed testbed = ur5_testbed();
  const SimulatedDataset a = simulate_dataset(testbed, Dataset::kA1, {3, std::nullopt});
  const SimulatedDataset b = simulate_dataset(testbed, Dataset::kA1, {3, std::nullopt});
  const SimulatedDataset c = simulate_dataset(testbed, Dataset::kA1, {4, std::nullopt});
  ASSERT_EQ(a.readings.size(), b.readings.size());
  for (std::size_t k = 0; k < a.readings.size(); ++k) {
    ASSERT_TRUE((a.readings[k].sensor_m.array() == b.readings[k].sensor_m.array()).all()) << k;
  }
  EXPECT_NE(a.robot.dh_delta[1].theta_offset_rad, c.robot.dh_delta[1].theta_offset_rad);
  EXPECT_FALSE((a.readings[0].sensor_m.array() == c.readings[0].sensor_m.array()).all());
}

TEST(Acquisition, SameSeedSameRobotInEveryDataset) {
  const Testbed testbed = ur5_testbed();
  const SimulatedDataset a1 = simulate_dataset(testbed, Dataset::kA1, {5, std::nullopt});
  const SimulatedDataset b = simulate_dataset(testbed, Dataset::kB, {5, std::nullopt});
  for (std::size_t i = 0; i < a1.robot.dh_delta.size(); ++i) {
    EXPECT_EQ(a1.robot.dh_delta[i].theta_offset_rad, b.robot.dh_delta[i].theta_offset_rad);
    EXPECT_EQ(a1.robot.transmission_phase_rad[i], b.robot.transmission_phase_rad[i]);
  }
}

TEST(Acquisition, UrControllerKeepsOneConfigurationAndReachesEveryPose) {
  const Testbed testbed = ur5_testbed();
  const SimulatedDataset data = simulate_dataset(testbed, Dataset::kA1, {});
  const auto label = kinematics::ur_configuration(testbed.nominal, data.visits.front().q_rad);
  for (const SimulatedVisit& v : data.visits) {
    const auto& loc = data.locations[static_cast<std::size_t>(v.location)];
    const Eigen::Isometry3d T = kinematics::forward_kinematics(testbed.nominal, v.q_rad);
    ASSERT_EIGEN_NEAR(T.translation(), loc.robot_m, 1e-9);
    ASSERT_EIGEN_NEAR(T.linear(), testbed.tcp_rotation, 1e-9);
    ASSERT_EQ(kinematics::ur_configuration(testbed.nominal, v.q_rad), label) << loc.point;
    EXPECT_EQ(v.config, 0);
  }
}

TEST(Acquisition, RepeatReadingsAndVisitsHaveTheConfiguredSpread) {
  const Testbed testbed = ur5_testbed();
  TestbedErrorModel errors = testbed.default_errors;
  errors.tracker.noise_sigma_m = Eigen::Vector3d(0.05e-3, 0.06e-3, 0.08e-3);
  const SimulatedDataset data = simulate_dataset(testbed, Dataset::kA1, {11, errors});
  // Tracker: per-axis sample variance of the K repeats, pooled over visits (sensor axes).
  const Points3 mean = visit_means_m(data);
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();
  for (const SimulatedReading& r : data.readings) {
    sum_sq += (r.sensor_m - mean.col(r.visit)).cwiseAbs2();
  }
  const double dof = static_cast<double>(data.readings.size() - data.visits.size());
  const Eigen::Vector3d sigma = (sum_sq / dof).cwiseSqrt();
  EXPECT_EIGEN_NEAR(sigma, errors.tracker.noise_sigma_m, 0.02 * 0.08e-3);
  // Robot: one repeatability draw per visit around the actual (error-affected) TCP.
  const SimulatedRobot robot(testbed.nominal, data.errors.robot, data.robot);
  Eigen::Vector3d rep_sq = Eigen::Vector3d::Zero();
  for (const SimulatedVisit& v : data.visits) {
    rep_sq += (v.tcp_m - robot.actual_tcp_m(v.q_rad)).cwiseAbs2();
  }
  const Eigen::Vector3d rep = (rep_sq / static_cast<double>(data.visits.size())).cwiseSqrt();
  EXPECT_EIGEN_NEAR(rep, Eigen::Vector3d::Constant(errors.robot.repeatability_sigma_m),
                    0.06 * errors.robot.repeatability_sigma_m);
}

TEST(Acquisition, LargeUr5DatasetsHaveThePapersCounts) {
  const Testbed testbed = ur5_testbed();
  const SimulatedDataset a2 = simulate_dataset(testbed, Dataset::kA2, {});
  EXPECT_EQ(a2.visits.size(), 8925u);
  EXPECT_EQ(a2.readings.size(), 8925u * 12u);
  const SimulatedDataset b = simulate_dataset(testbed, Dataset::kB, {});
  EXPECT_EQ(b.visits.size(), 9720u);
  EXPECT_EQ(b.readings.size(), 9720u * 12u);
}

}  // namespace
}  // namespace vrreg::simulation
