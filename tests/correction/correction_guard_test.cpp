// SPDX-License-Identifier: Apache-2.0
// The guard every correction passes (correction_guard.hpp): its figures by hand, and for every
// method a field of pure noise (no correction can beat none: every target answered uncorrected,
// status "correction not better than none", sd the uncorrected RMS) against a systematic field
// (applied). Also `auto`'s ranking, recomputed by hand: each method's misses at their uncorrected
// error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <limits>
#include <numeric>

#include "vrreg/correction/correction_guard.hpp"
#include "vrreg/correction/corrector.hpp"
#include "vrreg/correction/cross_validation.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

CorrectorData field_of(const Points3& robot_m, double systematic_m, double noise_m,
                       std::uint64_t seed) {
  Random rng(seed);
  CorrectorData d;
  d.fiducials_robot_m = robot_m;
  d.registered_robot_m = robot_m;
  d.corrections_sensor_m.resize(3, robot_m.cols());
  for (Eigen::Index j = 0; j < robot_m.cols(); ++j) {
    const Eigen::Vector3d p = robot_m.col(j);
    d.corrections_sensor_m.col(j) =
        systematic_m * Eigen::Vector3d(std::sin(12.0 * p.x()), std::cos(10.0 * p.y()),
                                       std::sin(9.0 * p.z() + 4.0 * p.x())) +
        rng.normal3(noise_m);
  }
  return d;
}

TEST(CorrectionGuard, FiguresAreTheRmsOverThePredictedFoldUnits) {
  // Fiducials 0 and 1 are one unit (a repeated reading), 2 was not predicted, 3..13 stand alone:
  // 12 units judged.
  const Eigen::Index n = 14;
  CorrectorData d;
  d.fiducials_robot_m = Points3::Zero(3, n);
  d.registered_robot_m = d.fiducials_robot_m;
  d.corrections_sensor_m = Points3::Zero(3, n);
  d.corrections_sensor_m.col(0) << 3, 4, 0;  // |c|^2 = 25
  d.corrections_sensor_m.col(1) << 1, 0, 0;  // 1
  d.corrections_sensor_m.col(2) << 0, 0, 5;
  d.corrections_sensor_m.col(3) << 2, 0, 0;  // 4
  for (Eigen::Index j = 4; j < n; ++j) d.corrections_sensor_m.col(j) << 0, 3, 0;  // 9
  std::vector<Eigen::Index> units(static_cast<std::size_t>(n));
  std::iota(units.begin(), units.end(), Eigen::Index{-1});
  units[0] = 0;
  CrossValidationRow row;
  row.method = InterpolationMethod::kRbf;
  row.applicable = true;
  row.squared_error_m2.setConstant(n, 4.0);
  row.squared_error_m2(0) = 9.0;
  row.squared_error_m2(1) = 1.0;
  row.squared_error_m2(2) = kNaN;
  row.squared_error_m2(3) = 16.0;
  const CorrectionGuard g = judge_correction(row, d, units);
  ASSERT_TRUE(g.judged) << g.note;
  EXPECT_EQ(g.n_judged, 13);
  EXPECT_EQ(g.judged_by, InterpolationMethod::kRbf);
  EXPECT_DOUBLE_EQ(g.cv_rms_m, std::sqrt((5.0 + 16.0 + 10 * 4.0) / 12.0));
  EXPECT_DOUBLE_EQ(g.uncorrected_rms_m, std::sqrt((13.0 + 4.0 + 10 * 9.0) / 12.0));
  EXPECT_TRUE(g.applied);
  for (Eigen::Index j = 4; j < n; ++j) row.squared_error_m2(j) = 16.0;  // 181 / 12 > 107 / 12
  EXPECT_FALSE(judge_correction(row, d, units).applied);
  // Eleven units predicted: too few to judge by.
  row.squared_error_m2(n - 1) = kNaN;
  const CorrectionGuard few = judge_correction(row, d, units);
  EXPECT_FALSE(few.judged);
  EXPECT_TRUE(few.applied);
  EXPECT_EQ(few.note, "only 11 held-out fiducials predicted, too few to judge the correction by");
  row.applicable = false;
  row.note = "fewer than 12 fiducials";
  const CorrectionGuard unjudged = judge_correction(row, d, units);
  EXPECT_FALSE(unjudged.judged);
  EXPECT_TRUE(unjudged.applied);
  EXPECT_EQ(unjudged.note, "fewer than 12 fiducials");
}

struct GuardCase {
  InterpolationMethod method;
  bool lattice;
};

class CorrectionGuardMethods : public ::testing::TestWithParam<GuardCase> {};

TEST_P(CorrectionGuardMethods, NoiseIsNotCorrectedASystematicFieldIs) {
  const GuardCase& param = GetParam();
  if (testing::sanitized() && param.method == InterpolationMethod::kKriging) GTEST_SKIP();
  const double spacing_m = 0.04;
  Points3 fiducials_m = testing::cube_grid_m(5, spacing_m);
  if (!param.lattice) {  // the lattice's nodes moved a third of a spacing at random
    Random rng(5);
    for (Eigen::Index j = 0; j < fiducials_m.cols(); ++j) {
      for (int a = 0; a < 3; ++a) fiducials_m(a, j) += rng.uniform(-spacing_m / 3.0, spacing_m / 3.0);
    }
  }
  const Points3 targets_m = testing::cube_grid_m(4, spacing_m, spacing_m / 2.0);
  for (const double systematic_m : {0.0, 5e-4}) {
    SCOPED_TRACE(std::string(to_string(param.method)) + (param.lattice ? " lattice" : " scattered") +
                 ", systematic " + std::to_string(systematic_m));
    const CorrectorData d = field_of(fiducials_m, systematic_m, 2e-5, 3);
    CorrectorOptions options;
    options.interpolation.method = param.method;
    if (param.method == InterpolationMethod::kOctuplet) options.interpolation.cube_edge_m = spacing_m;
    const Corrector c = Corrector::fit(d, options);
    ASSERT_TRUE(c.guard());
    const CorrectionGuard& g = *c.guard();
    ASSERT_TRUE(g.judged) << g.note;
    EXPECT_EQ(c.applied(), systematic_m > 0.0)
        << "cv " << g.cv_rms_m << " m, uncorrected " << g.uncorrected_rms_m << " m";
    const TargetCorrection t = c.correct(CorrectionQuery(targets_m, targets_m, Eigen::MatrixXd()));
    ASSERT_TRUE(t.guard);
    EXPECT_EQ(t.guard->applied, c.applied());
    for (Eigen::Index i = 0; i < targets_m.cols(); ++i) {
      const StencilStatus s = t.stencils[static_cast<std::size_t>(i)].status;
      if (c.applied()) {
        EXPECT_NE(s, StencilStatus::kNotBetterThanNone);
        continue;
      }
      ASSERT_EQ(s, StencilStatus::kNotBetterThanNone) << i;
      EXPECT_EQ(t.corrected_robot_m.col(i), t.uncorrected_robot_m.col(i));
      EXPECT_TRUE(t.corrections_sensor_m.col(i).isZero());
      if (t.predicted_sd_m.size() > 0) {
        EXPECT_EQ(t.predicted_sd_m(i), g.uncorrected_rms_m);
      }
    }
    if (!c.applied()) {
      EXPECT_EQ(t.n_flagged, targets_m.cols());
    }
    // Saved and restored, the decision and its figures stay.
    const Corrector back = Corrector::restore(c.save(), d);
    ASSERT_TRUE(back.guard());
    EXPECT_EQ(back.applied(), c.applied());
    EXPECT_EQ(back.guard()->cv_rms_m, g.cv_rms_m);
    EXPECT_EQ(back.guard()->uncorrected_rms_m, g.uncorrected_rms_m);
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryMethod, CorrectionGuardMethods,
    ::testing::Values(GuardCase{InterpolationMethod::kLinear, true},
                      GuardCase{InterpolationMethod::kLinear, false},
                      GuardCase{InterpolationMethod::kGrid, true},
                      GuardCase{InterpolationMethod::kOctuplet, true},
                      GuardCase{InterpolationMethod::kTrilinear, true},
                      GuardCase{InterpolationMethod::kScattered, false},
                      GuardCase{InterpolationMethod::kRbf, false},
                      GuardCase{InterpolationMethod::kKriging, false},
                      GuardCase{InterpolationMethod::kAuto, false}),
    [](const ::testing::TestParamInfo<GuardCase>& case_info) {
      return std::string(to_string(case_info.param.method)) +
             (case_info.param.lattice ? "_lattice" : "_scattered");
    });

TEST(CorrectionGuard, UnguardedCorrectorsCorrectNoiseAsAsked) {
  const CorrectorData d = field_of(testing::cube_grid_m(5, 0.04), 0.0, 2e-5, 3);
  CorrectorOptions options;
  options.interpolation.method = InterpolationMethod::kTrilinear;
  options.guard = false;
  const Corrector c = Corrector::fit(d, options);
  EXPECT_FALSE(c.guard());
  EXPECT_TRUE(c.applied());
}

TEST(CorrectionGuard, FewerFiducialsThanFoldsCanJudgeAreAppliedAndSaySo) {
  const CorrectorData d = field_of(testing::cube_grid_m(2, 0.04), 0.0, 2e-5, 3);
  CorrectorOptions options;
  options.interpolation.method = InterpolationMethod::kLinear;
  const Corrector c = Corrector::fit(d, options);
  ASSERT_TRUE(c.guard());
  EXPECT_FALSE(c.guard()->judged);
  EXPECT_TRUE(c.applied());
  EXPECT_EQ(c.guard()->note, "fewer than 12 fiducials");
}

// auto ranks every method on the fiducials any method predicted, its misses there at their
// uncorrected error; recomputed here from the rows' own held-out errors.
TEST(CorrectionGuard, AutoRanksEachMethodWithItsMissesAtTheUncorrectedError) {
  const CorrectorData d = field_of(testing::cube_grid_m(6, 0.04), 5e-4, 2e-5, 9);
  const CrossValidation cv = choose_by_cross_validation(d, MethodSettings{}, 5, 1);
  std::vector<char> ranked(static_cast<std::size_t>(d.size()), 0);
  for (const CrossValidationRow& row : cv.rows) {
    if (!row.applicable) continue;
    for (Eigen::Index j = 0; j < d.size(); ++j)
      if (!std::isnan(row.squared_error_m2(j))) ranked[static_cast<std::size_t>(j)] = 1;
  }
  const auto n = std::count(ranked.begin(), ranked.end(), char{1});
  EXPECT_EQ(cv.n_ranked, n);
  double best = std::numeric_limits<double>::infinity();
  InterpolationMethod best_method = InterpolationMethod::kAuto;
  bool some_miss = false;
  for (const CrossValidationRow& row : cv.rows) {
    if (!row.applicable) continue;
    double sum = 0.0;
    for (Eigen::Index j = 0; j < d.size(); ++j) {
      if (ranked[static_cast<std::size_t>(j)] == 0) continue;
      const bool miss = std::isnan(row.squared_error_m2(j));
      some_miss = some_miss || miss;
      sum += miss ? d.corrections_sensor_m.col(j).squaredNorm() : row.squared_error_m2(j);
    }
    const double rms = std::sqrt(sum / static_cast<double>(n));  // a lattice: one fiducial a unit
    EXPECT_NEAR(row.rms_ranked_m, rms, 1e-12 * rms) << to_string(row.method);
    if (rms < best) {
      best = rms;
      best_method = row.method;
    }
  }
  EXPECT_TRUE(some_miss);  // trilinear and scattered cannot predict the lattice's faces
  EXPECT_EQ(cv.chosen, best_method);
}

}  // namespace
}  // namespace vrreg
