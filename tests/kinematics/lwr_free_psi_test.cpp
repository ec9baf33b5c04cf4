// SPDX-License-Identifier: Apache-2.0
// The LWR 4+ with its arm angle free: every configuration that some psi brings within the joint
// limits is returned, at psi = 0 when that is feasible and otherwise near 0 inside the feasible
// range, and reproduces the pose.
#include "vrreg/kinematics/lwr_free_psi.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "kinematics_test_support.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg::kinematics {
namespace {

TEST(LwrFreePsi, ArmAngleNearestZeroInsideTheFeasibleRange) {
  const double m = kFreePsiMarginRad;
  EXPECT_FALSE(free_arm_angle({}));
  EXPECT_EQ(*free_arm_angle({{-0.2, 0.4}}), 0.0);
  EXPECT_NEAR(*free_arm_angle({{-1.0, -0.5}, {0.3, 2.0}}), 0.3 + m, 1e-15);
  EXPECT_NEAR(*free_arm_angle({{-1.0, -0.25}, {0.3, 2.0}}), -0.25 - m, 1e-15);
  EXPECT_NEAR(*free_arm_angle({{0.50, 0.51}}), 0.505, 1e-15);      // narrower than two margins
  EXPECT_NEAR(*free_arm_angle({{-0.01, 0.5}}), -0.01 + m, 1e-15);  // 0 too near the limit
}

TEST(LwrFreePsi, EveryFeasibleConfigurationAtItsArmAngle) {
  const SerialChain chain = lwr4();
  Random rng(29);
  const int poses = ::vrreg::testing::sanitized() ? 100 : 1000;
  int rescued = 0;
  for (int k = 0; k < poses; ++k) {
    const JointVector q = testing::random_joints(rng, chain);
    const Eigen::Isometry3d t = forward_kinematics(chain, q);
    const IkResult r = inverse_kinematics(chain, t);
    ASSERT_TRUE(r.ok()) << r.message;  // q itself is within the limits
    const PsiIntervalsResult feasible = lwr_feasible_psi(chain, t);
    int expected = 0;
    for (const auto& list : feasible.intervals) expected += list.empty() ? 0 : 1;
    if (r.singular == kNoSingularity) {
      EXPECT_EQ(static_cast<int>(r.solutions.size()), expected);
    }
    bool has_own = false;
    for (const IkSolution& s : r.solutions) {
      ASSERT_TRUE(s.psi_rad);
      const auto& list = feasible.intervals[static_cast<std::size_t>(s.config.index())];
      EXPECT_EQ(*s.psi_rad, *free_arm_angle(list));
      const testing::PoseError e = testing::pose_error(forward_kinematics(chain, s.q_rad), t);
      EXPECT_LE(e.position_m, 1e-12);
      EXPECT_LE(e.rotation_rad, 1e-12);
      for (int i = 0; i < 7; ++i) {
        EXPECT_GE(s.q_rad(i), chain.limit(i).lower_rad);
        EXPECT_LE(s.q_rad(i), chain.limit(i).upper_rad);
      }
      has_own = has_own || s.config == lwr_configuration(chain, q);
    }
    EXPECT_TRUE(has_own);
    rescued += lwr_inverse_kinematics(chain, t, 0.0).ok() ? 0 : 1;
  }
  // Poses that psi = 0 alone would have refused (each is reachable within the limits).
  EXPECT_GT(rescued, 0);
  std::printf("[ lwr4 ] %d poses, %d refused at psi = 0, all solved with psi free\n", poses,
              rescued);
}

}  // namespace
}  // namespace vrreg::kinematics
