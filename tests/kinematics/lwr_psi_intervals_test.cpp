#include "vrreg/kinematics/lwr_psi_intervals.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "kinematics_test_support.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg::kinematics {
namespace {

constexpr double kPi = std::numbers::pi;

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

TEST(LwrPsiIntervals, AgreeWithDenseSampling) {
  const SerialChain chain = lwr4();
  Random rng(17);
  const int poses = ::vrreg::testing::sanitized() ? 30 : 300;
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

TEST(LwrPsiIntervals, TheOwnArmAngleOfASampleIsInItsConfigurationsInterval) {
  const SerialChain chain = lwr4();
  Random rng(3);
  for (int k = 0; k < 2000; ++k) {
    const JointVector q = testing::random_joints(rng, chain);
    const LwrArmState state = lwr_arm_state(chain, q);
    const PsiIntervalsResult r = lwr_feasible_psi(chain, state.T_base_tcp);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(inside(r.intervals[static_cast<std::size_t>(state.config.index())], state.psi_rad,
                       -1e-9))
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

TEST(LwrPsiIntervals, UnreachablePose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() << 2.0, 0.0, 0.0;
  const PsiIntervalsResult r = lwr_feasible_psi(lwr4(), t);
  EXPECT_EQ(r.status, IkStatus::kUnreachable);
  for (const auto& list : r.intervals) EXPECT_TRUE(list.empty());
}

}  // namespace
}  // namespace vrreg::kinematics
