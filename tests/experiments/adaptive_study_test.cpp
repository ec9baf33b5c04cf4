// SPDX-License-Identifier: Apache-2.0
// The adaptive-planning study, quick (Procedure 1 at a = 50 and 5 mm, batches of 60), one seed
// per test bed: the done-when criteria it meets (docs/adaptive.md has the full table).
#include "vrreg/experiments/adaptive_study.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg::experiments {
namespace {

const AdaptiveVerdict& verdict_of(const AdaptiveStudyResult& r, const std::string& robot) {
  for (const AdaptiveVerdict& v : r.verdicts) {
    if (v.robot == robot) return v;
  }
  throw InputError("no verdict for " + robot);
}

// UR5 and LWR 4+ seed 3 in one run (the two cells in parallel). Both: at most a quarter of
// Procedure 1's fiducials at d_min, and the stopping prediction within +-20 % of the measured
// RMS_T. The LWR also reaches Procedure 1's RMS_T at d_min within 10 %; the UR5 does not: its
// octuplet at a = 5 mm averages 8 fiducials within 4.3 mm of each target, which a quarter of
// them (2 per target) cannot match at its noise (docs/adaptive.md), so the UR5 is held to
// 1.5 x Procedure 1's and to beating Procedure 1 at d_max.
TEST(AdaptiveStudy, QuickOnBothTestBeds) {
  if (testing::sanitized()) GTEST_SKIP() << "a dozen kriging fits: release build only";
  AdaptiveStudyOptions o;
  o.seeds = {3};
  const AdaptiveStudyResult r = run_adaptive_study(quick_study_options(o));
  ASSERT_EQ(r.verdicts.size(), 2u);
  ASSERT_EQ(r.n_targets, (std::vector<int>{120, 150}));
  ASSERT_EQ(r.fixed.size(), 4u);  // per robot: Procedure 1 at 50 and 5 mm
  for (const AdaptiveRun& a : r.adaptive) {
    ASSERT_FALSE(a.batches.empty()) << a.robot;
    // Batches of 60, the readings the test bed takes per location, robot time at the rates.
    const AdaptiveBatch& b = a.batches.back();
    const long long repeats = a.robot == "ur5" ? 12 : 1;
    EXPECT_EQ(b.n_readings, repeats * b.n_fiducials) << a.robot;
    EXPECT_NEAR(b.robot_time_s, 2.5 * b.n_fiducials + 0.1 * static_cast<double>(b.n_readings),
                1e-9);
    EXPECT_EQ(a.batches.front().n_fiducials, 60) << a.robot;
    EXPECT_TRUE(std::isnan(a.batches.front().measured_rms_t_m)) << a.robot;  // at STOP only
  }
  for (const AdaptiveVerdict& v : r.verdicts) {
    EXPECT_TRUE(v.quarter) << v.robot << ": " << v.adaptive_fiducials << " of "
                           << v.procedure1_dmin_fiducials;
    EXPECT_TRUE(v.honest) << v.robot << ": measured / predicted " << v.measured_over_predicted;
    EXPECT_NEAR(v.goal_sd_m, 1.1 * v.procedure1_dmin_rms_t_m, 1e-15);
  }
  // Seed 3: UR5 Procedure 1 at d_min 960 fiducials, 0.100 mm; adaptive 240, 0.142 mm, measured
  // / predicted 0.99. LWR: 1200, 0.126 mm; adaptive 300, 0.132 mm, 0.92.
  const AdaptiveVerdict& lwr = verdict_of(r, "lwr4");
  EXPECT_TRUE(lwr.reaches) << lwr.adaptive_rms_t_m << " vs " << lwr.procedure1_dmin_rms_t_m;
  const AdaptiveVerdict& ur5 = verdict_of(r, "ur5");
  EXPECT_LT(ur5.adaptive_rms_t_m, 1.5 * ur5.procedure1_dmin_rms_t_m);
  EXPECT_LT(ur5.adaptive_rms_t_m, r.fixed[0].rms_t_m);  // Procedure 1 at a = 50 mm
  // Procedure 1's octuplets: 8 per target, d = sqrt(3)/2 a.
  EXPECT_EQ(r.fixed[1].n_fiducials, 8 * 120);
  EXPECT_NEAR(r.fixed[1].d_m, std::sqrt(3.0) / 2.0 * 0.005, 1e-15);
}

TEST(AdaptiveStudy, BadOptionsAreRefused) {
  AdaptiveStudyOptions o;
  o.robots = {"ur10"};
  EXPECT_THROW(o.validate(), InputError);
  o = {};
  o.seeds.clear();
  EXPECT_THROW(o.validate(), InputError);
  o = {};
  o.goal_sd_m = -1.0;
  EXPECT_THROW(o.validate(), InputError);
  o = {};
  o.cube_edges_m = {0.0};
  EXPECT_THROW(o.validate(), InputError);
  o = {};
  o.min_relative_gain = 1.0;
  EXPECT_THROW(o.validate(), InputError);
}

}  // namespace
}  // namespace vrreg::experiments
