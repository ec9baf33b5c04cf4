// SPDX-License-Identifier: Apache-2.0
// The KUKA LWR 4+ grid: serpentine path of unit steps, four configurations per location in the
// analytic IK's order (which changes over part of the volume, never at random), joints recorded.
#include <algorithm>
#include <map>
#include <set>

#include "simulation_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/aik_order.hpp"
#include "vrreg_test.hpp"

namespace vrreg::simulation {
namespace {

TEST(Serpentine, VisitsEveryNodeOnceInUnitSteps) {
  for (const Eigen::Vector3i& n : {Eigen::Vector3i(13, 11, 11), Eigen::Vector3i(4, 3, 2),
                                   Eigen::Vector3i(5, 6, 4), Eigen::Vector3i(1, 1, 3)}) {
    const std::vector<Eigen::Vector3i> order = serpentine_order(n.x(), n.y(), n.z());
    ASSERT_EQ(order.size(), static_cast<std::size_t>(n.prod()));
    std::set<std::tuple<int, int, int>> seen;
    for (std::size_t k = 0; k < order.size(); ++k) {
      seen.emplace(order[k].x(), order[k].y(), order[k].z());
      ASSERT_TRUE((order[k].array() >= 0).all() && (order[k].array() < n.array()).all());
      if (k > 0) {
        ASSERT_EQ((order[k] - order[k - 1]).cwiseAbs().sum(), 1) << "step " << k;
      }
    }
    EXPECT_EQ(seen.size(), order.size());
  }
  EXPECT_THROW(serpentine_order(0, 2, 2), InputError);
}

TEST(LwrGrid, PathStepsAreOneGridStepOf20mm) {
  const std::vector<PlannedLocation> plan = plan_dataset(lwr4_testbed(), Dataset::kGrid);
  ASSERT_EQ(plan.size(), 1573u);
  for (std::size_t k = 1; k < plan.size(); ++k) {
    ASSERT_NEAR((plan[k].robot_m - plan[k - 1].robot_m).norm(), 0.020, 1e-12) << k;
  }
}

class LwrGridData : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    data_ = new SimulatedDataset(simulate_dataset(lwr4_testbed(), Dataset::kGrid, {2, {}}));
  }
  static void TearDownTestSuite() {
    delete data_;
    data_ = nullptr;
  }
  static SimulatedDataset* data_;
};
SimulatedDataset* LwrGridData::data_ = nullptr;

TEST_F(LwrGridData, FourConfigurationsPerLocationOneReadingEach) {
  const Testbed testbed = lwr4_testbed();
  const SimulatedDataset& data = *data_;
  ASSERT_EQ(data.visits.size(), 4u * 1573u);
  ASSERT_EQ(data.readings.size(), data.visits.size());
  for (std::size_t v = 0; v < data.visits.size(); ++v) {
    const SimulatedVisit& visit = data.visits[v];
    EXPECT_EQ(visit.location, static_cast<int>(v / 4));
    EXPECT_EQ(visit.config, static_cast<int>(v % 4) + 1);
    ASSERT_EQ(visit.q_rad.size(), 7);
    EXPECT_TRUE(testbed.nominal.within_limits(visit.q_rad));
    const Eigen::Isometry3d T = kinematics::forward_kinematics(testbed.nominal, visit.q_rad);
    ASSERT_EIGEN_NEAR(T.translation(),
                      data.locations[static_cast<std::size_t>(visit.location)].robot_m, 1e-9);
  }
  // The four visits of a location are four different global configurations.
  for (std::size_t p = 0; p < data.locations.size(); ++p) {
    std::set<int> configs;
    for (std::size_t m = 0; m < 4; ++m) {
      configs.insert(
          kinematics::lwr_configuration(testbed.nominal, data.visits[4 * p + m].q_rad).index());
    }
    ASSERT_EQ(configs.size(), 4u) << data.locations[p].point;
  }
}

TEST_F(LwrGridData, EnumerationOrderChangesOverPartOfTheVolumeOnly) {
  // The order of global configurations the IK lists, compared with the most common one (the
  // first location may lie in a changed region: it does from the test bed's home posture).
  const Testbed testbed = lwr4_testbed();
  const SimulatedDataset& data = *data_;
  const auto order_at = [&](std::size_t p) {
    std::vector<int> order;
    for (std::size_t m = 0; m < 4; ++m) {
      order.push_back(
          kinematics::lwr_configuration(testbed.nominal, data.visits[4 * p + m].q_rad).index());
    }
    return order;
  };
  std::map<std::vector<int>, int> count;
  for (std::size_t p = 0; p < data.locations.size(); ++p) ++count[order_at(p)];
  const std::vector<int> usual =
      std::max_element(count.begin(), count.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;
      })->first;
  int changed = 0;
  int changes_along_path = 0;
  for (std::size_t p = 0; p < data.locations.size(); ++p) {
    changed += order_at(p) != usual ? 1 : 0;
    if (p > 0 && order_at(p) != order_at(p - 1)) ++changes_along_path;
  }
  const double fraction = static_cast<double>(changed) / static_cast<double>(data.locations.size());
  EXPECT_GT(fraction, 0.10);
  EXPECT_LT(fraction, 0.20);
  // Regions, not a shuffle: few changes along the path (a shuffle changes at almost every
  // step) and the changed locations form few connected regions of the grid.
  EXPECT_LT(changes_along_path,
            static_cast<int>(0.15 * static_cast<double>(data.locations.size())));
  const std::vector<Eigen::Vector3i> nodes = serpentine_order(13, 11, 11);
  std::vector<int> state(13 * 11 * 11, 0);  // 1 = changed, 2 = changed and visited
  const auto at = [](const Eigen::Vector3i& n) { return n.x() + 13 * (n.y() + 11 * n.z()); };
  for (std::size_t p = 0; p < nodes.size(); ++p) state[at(nodes[p])] = order_at(p) != usual ? 1 : 0;
  int regions = 0;
  for (int start = 0; start < static_cast<int>(state.size()); ++start) {
    if (state[start] != 1) continue;
    ++regions;
    std::vector<Eigen::Vector3i> stack = {{start % 13, (start / 13) % 11, start / 143}};
    state[start] = 2;
    while (!stack.empty()) {
      const Eigen::Vector3i n = stack.back();
      stack.pop_back();
      for (int axis = 0; axis < 3; ++axis) {
        for (int step : {-1, 1}) {
          Eigen::Vector3i m = n;
          m(axis) += step;
          if ((m.array() < 0).any() || m.x() >= 13 || m.y() >= 11 || m.z() >= 11) continue;
          if (state[at(m)] == 1) {
            state[at(m)] = 2;
            stack.push_back(m);
          }
        }
      }
    }
  }
  EXPECT_LE(regions, 3);
  // The last label is always the same configuration (as in the paper: no switch in config 4).
  for (std::size_t p = 0; p < data.locations.size(); ++p) ASSERT_EQ(order_at(p)[3], usual[3]);
}

TEST(AikOrder, SortsByDistanceToHome) {
  const Testbed testbed = lwr4_testbed();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = testbed.tcp_rotation;
  pose.translation() = testbed.volume_centre_m;
  const kinematics::IkResult ik =
      kinematics::lwr_inverse_kinematics(testbed.nominal, pose, testbed.arm_angle_rad);
  ASSERT_EQ(ik.solutions.size(), 4u);
  const auto ordered = aik_order(ik.solutions, testbed.home_q_rad);
  ASSERT_EQ(ordered.size(), 4u);
  for (std::size_t m = 1; m < ordered.size(); ++m) {
    EXPECT_LE(kinematics::joint_distance_l2(ordered[m - 1].q_rad, testbed.home_q_rad),
              kinematics::joint_distance_l2(ordered[m].q_rad, testbed.home_q_rad));
  }
}

}  // namespace
}  // namespace vrreg::simulation
