// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/lwr_psi_intervals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kinematics_test_support.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg::kinematics {
namespace {

using units::kPi;

bool inside(const std::vector<PsiInterval>& list, double psi, double margin) {
  for (const PsiInterval& i : list) {
    if (psi >= i.lower_rad + margin && psi <= i.upper_rad - margin) return true;
  }
  return false;
}

bool near_boundary(const std::vector<PsiInterval>& list, double psi, double margin) {
  for (const PsiInterval& i : list) {
    if (std::abs(psi - i.lower_rad) < margin || std::abs(psi - i.upper_rad) < margin) return true;
  }
  return false;
}

SerialChain calibrated_lwr() {
  std::vector<DhRow> rows = lwr4().rows();
  for (std::size_t i = 0; i < 7; ++i) rows[i].theta_offset_rad = -0.02 * static_cast<double>(i);
  std::vector<JointLimits> limits = lwr4().limits();
  limits[2] = {-1.0, 2.5};  // asymmetric
  return SerialChain("lwr-cal", rows, limits)
      .with_tool(testing::pose_from({0.0, 0.03, 0.05}, 0.0, 0.3, 0.0));
}

class LwrPsiIntervals : public ::testing::TestWithParam<bool> {};

TEST_P(LwrPsiIntervals, AgreeWithDenseSampling) {
  const SerialChain chain = GetParam() ? calibrated_lwr() : lwr4();
  Random rng(17);
  const int poses = ::vrreg::testing::sanitized() ? 30 : 200;
  const int samples = 3600;  // 0.1 deg
  long mismatches = 0, checked = 0;
  for (int k = 0; k < poses; ++k) {
    const Eigen::Isometry3d t = forward_kinematics(chain, testing::random_joints(rng, chain));
    const PsiIntervalsResult intervals = lwr_feasible_psi(chain, t);
    ASSERT_TRUE(intervals.ok()) << intervals.message;  // the sample itself is feasible
    for (int s = 0; s < samples; ++s) {
      const double psi = -kPi + 2 * kPi * (s + 0.5) / samples;
      const IkResult r = lwr_inverse_kinematics(chain, t, psi);
      bool feasible[8] = {};
      for (const IkSolution& sol : r.solutions) feasible[sol.config.index()] = true;
      for (std::size_t c = 0; c < 8; ++c) {
        const auto& list = intervals.intervals[c];
        if (near_boundary(list, psi, 1e-9)) continue;
        ++checked;
        if (feasible[c] != inside(list, psi, 0.0)) ++mismatches;
      }
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << checked;
}

INSTANTIATE_TEST_SUITE_P(NominalAndCalibrated, LwrPsiIntervals, ::testing::Bool());

TEST(LwrPsiIntervalsOwn, TheOwnArmAngleOfASampleIsInItsConfigurationsInterval) {
  const SerialChain chain = lwr4();
  Random rng(3);
  for (int k = 0; k < 2000; ++k) {
    const JointVector q = testing::random_joints(rng, chain);
    const LwrArmState state = lwr_arm_state(chain, q);
    const PsiIntervalsResult r = lwr_feasible_psi(chain, state.T_base_tcp);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(
        inside(r.intervals[static_cast<std::size_t>(state.config.index())], state.psi_rad, -1e-9))
        << "psi " << state.psi_rad << " config " << state.config.to_string();
    for (const auto& list : r.intervals) {
      for (std::size_t i = 0; i < list.size(); ++i) {
        EXPECT_LE(list[i].lower_rad, list[i].upper_rad);
        if (i > 0) {
          EXPECT_LT(list[i - 1].upper_rad, list[i].lower_rad);
        }
      }
    }
  }
}

TEST(LwrPsiIntervalsOwn, UnreachablePose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() << 2.0, 0.0, 0.0;
  const PsiIntervalsResult r = lwr_feasible_psi(lwr4(), t);
  EXPECT_EQ(r.status, IkStatus::kUnreachable);
  for (const auto& list : r.intervals) EXPECT_TRUE(list.empty());
}

}  // namespace
}  // namespace vrreg::kinematics
