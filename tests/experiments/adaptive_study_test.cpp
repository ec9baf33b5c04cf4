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

// UR5 and LWR 4+ seed 3 in one run (the two cells in parallel), the loop correcting with the
// joint-space model and stopping on its predicted sd: on both, Procedure 1's RMS_T at d_min
// within 10 % with at most a quarter of its fiducials, and the stopping prediction within +-20 %
// of the measured RMS_T (docs/adaptive.md has the table over seeds 3-5).
TEST(AdaptiveStudy, QuickOnBothTestBeds) {
  if (testing::sanitized()) GTEST_SKIP() << "joint-model and kriging fits: release build only";
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
  for (const AdaptiveRun& a : r.adaptive) {
    EXPECT_EQ(a.interpolation, "joint") << a.robot;
    EXPECT_EQ(a.batches.back().predicted_by, "joint") << a.robot;  // the stop judged its sd
    EXPECT_EQ(a.stop_reason, "the goal is reached") << a.robot;
  }
  // Seed 3: UR5 Procedure 1 at d_min 960 fiducials, 0.100 mm; adaptive 120, 0.101 mm, measured
  // / predicted 1.01. LWR: 1200, 0.126 mm; adaptive 180, 0.129 mm, 0.96.
  for (const AdaptiveVerdict& v : r.verdicts) {
    EXPECT_TRUE(v.reaches) << v.robot << ": " << v.adaptive_rms_t_m << " vs "
                           << v.procedure1_dmin_rms_t_m;
    EXPECT_TRUE(v.quarter) << v.robot << ": " << v.adaptive_fiducials << " of "
                           << v.procedure1_dmin_fiducials;
    EXPECT_TRUE(v.honest) << v.robot << ": measured / predicted " << v.measured_over_predicted;
    EXPECT_NEAR(v.goal_sd_m, 1.1 * v.procedure1_dmin_rms_t_m, 1e-15);
    EXPECT_LT(v.adaptive_rms_t_m, r.fixed[v.robot == "ur5" ? 0 : 2].rms_t_m);  // P1 at 50 mm
  }
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
