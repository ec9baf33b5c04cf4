// SPDX-License-Identifier: Apache-2.0
// The monitor check against independent references: chi-square quantiles from tables, the
// false-alarm rate by Monte Carlo on unchanged cells, an exact rigid motion recovered, a moved
// point named, a non-rigid change told apart.
#include "vrreg/core/check.hpp"
#include "vrreg/metrics/monitor_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "vrreg/core/random.hpp"
#include "vrreg/metrics/distributions.hpp"

namespace vrreg {
namespace {

TEST(ChiSquare, QuantilesAgreeWithTables) {
  // NIST/SEMATECH e-Handbook, upper critical values of the chi-square distribution.
  EXPECT_NEAR(chi_square_quantile_upper(0.05, 1), 3.841, 1e-3);
  EXPECT_NEAR(chi_square_quantile_upper(0.05, 2), 5.991, 1e-3);
  EXPECT_NEAR(chi_square_quantile_upper(0.01, 3), 11.345, 1e-3);
  EXPECT_NEAR(chi_square_quantile_upper(0.01, 6), 16.812, 1e-3);
  EXPECT_NEAR(chi_square_quantile_upper(0.01, 9), 21.666, 1e-3);
  EXPECT_NEAR(chi_square_quantile_upper(0.10, 30), 40.256, 1e-3);
  // k = 2: exp(-x/2) exactly.
  EXPECT_NEAR(chi_square_survival(4.0, 2), std::exp(-2.0), 1e-15);
  EXPECT_THROW(chi_square_survival(-1.0, 3), InputError);
}

TEST(FDistribution, QuantilesAgreeWithTables) {
  // NIST/SEMATECH e-Handbook, upper critical values of the F distribution.
  EXPECT_NEAR(f_quantile_upper(0.05, 3, 20), 3.098, 1e-3);
  EXPECT_NEAR(f_quantile_upper(0.01, 6, 60), 3.119, 1e-3);
  EXPECT_NEAR(f_quantile_upper(0.01, 9, 120), 2.559, 1e-3);
  // d1 = 2: P(F > x) = (1 + 2 x / d2)^(-d2 / 2) exactly.
  EXPECT_NEAR(f_survival(1.7, 2, 9), std::pow(1.0 + 2.0 * 1.7 / 9.0, -4.5), 1e-14);
  // Many denominator dof: k F -> chi2_k.
  EXPECT_NEAR(squared_sum_bound(0.01, 6, 1e7), chi_square_quantile_upper(0.01, 6), 1e-4);
  EXPECT_EQ(squared_sum_bound(0.01, 6, 0), chi_square_quantile_upper(0.01, 6));
  EXPECT_THROW(f_survival(1.0, 0.0, 3.0), InputError);
}

// Three monitor points 2-3 m from the tracker, spread over ~1 m.
Points3 monitors() {
  Points3 p(3, 3);
  p << 2.1, 2.6, 2.3,  //
      -0.4, 0.1, 0.5,  //
      0.2, 0.3, 0.9;
  return p;
}

TEST(MonitorCheck, FalseAlarmsAtTheStatedRate) {
  Random rng(3);
  const Points3 p = monitors();
  const Eigen::VectorXd sd = Eigen::VectorXd::Constant(3, 2e-5);
  const int runs = 20000;
  int alarms = 0;
  for (int r = 0; r < runs; ++r) {
    Points3 today = p;
    for (int i = 0; i < 3; ++i) today.col(i) += rng.normal3(2e-5);
    alarms += check_monitors(p, today, sd).verdict != MonitorVerdict::kValid ? 1 : 0;
  }
  const double rate = static_cast<double>(alarms) / runs;
  std::printf("false alarms %d of %d (%.4f, stated 0.01)\n", alarms, runs, rate);
  EXPECT_NEAR(rate, 0.01, 3 * std::sqrt(0.01 * 0.99 / runs));
}

TEST(MonitorCheck, AnEstimatedSdKeepsTheRateWithTheFTest) {
  // The sd is estimated from 12 squared normal draws per run (nu = 12): the chi-square bound
  // would raise false alarms, the F bound keeps the stated rate.
  Random rng(5);
  const Points3 p = monitors();
  const int runs = 20000;
  int alarms = 0;
  MonitorCheckOptions options;
  options.variance_dof = 12;
  for (int r = 0; r < runs; ++r) {
    double ss = 0.0;
    for (int k = 0; k < 12; ++k) ss += std::pow(rng.normal3(2e-5)(0), 2);
    const Eigen::VectorXd sd = Eigen::VectorXd::Constant(3, std::sqrt(ss / 12));
    Points3 today = p;
    for (int i = 0; i < 3; ++i) today.col(i) += rng.normal3(2e-5);
    alarms += check_monitors(p, today, sd, options).verdict != MonitorVerdict::kValid ? 1 : 0;
  }
  const double rate = static_cast<double>(alarms) / runs;
  std::printf("false alarms with an estimated sd %d of %d (%.4f, stated 0.01)\n", alarms, runs,
              rate);
  EXPECT_NEAR(rate, 0.01, 3 * std::sqrt(0.01 * 0.99 / runs));
}

TEST(MonitorCheck, ARigidMotionIsRecovered) {
  const Points3 p = monitors();
  const Eigen::Vector3d omega(1e-4, -0.5e-4, 0.8e-4);
  const Eigen::Vector3d t(5e-5, -8e-5, 2e-5);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix();
  const Points3 today = (rotation * p).colwise() + t;
  const MonitorCheck c = check_monitors(p, today, Eigen::VectorXd::Constant(3, 2e-5));
  EXPECT_EQ(c.verdict, MonitorVerdict::kRigidChange) << c.message;
  ASSERT_TRUE(c.rigid);
  // First order in omega: the second-order term is |omega|^2 |p| / 2 ~ 2e-8 m.
  EXPECT_LE((c.rigid->rotation_rad - omega).norm(), 1e-7);
  EXPECT_LE((c.rigid->translation_m - t).norm(), 5e-8);
}

TEST(MonitorCheck, BumpsAreDetectedAndOneMovedPointIsNamed) {
  Random rng(5);
  const Points3 p = monitors();
  const Eigen::VectorXd sd = Eigen::VectorXd::Constant(3, 2e-5);
  int detected = 0, rigid = 0;
  const int runs = 2000;
  for (int r = 0; r < runs; ++r) {
    // A 0.1 mm bump: a translation in a random direction.
    const Eigen::Vector3d t = 1e-4 * rng.normal3(1.0).normalized();
    Points3 today = p.colwise() + t;
    for (int i = 0; i < 3; ++i) today.col(i) += rng.normal3(2e-5);
    const MonitorCheck c = check_monitors(p, today, sd);
    detected += c.verdict != MonitorVerdict::kValid ? 1 : 0;
    rigid += c.verdict == MonitorVerdict::kRigidChange ? 1 : 0;
  }
  std::printf("0.1 mm bump, 3 points, sd 0.02 mm: detected %d, rigid %d of %d\n", detected, rigid,
              runs);
  EXPECT_GE(detected, 0.99 * runs);
  EXPECT_GE(rigid, 0.95 * runs);

  Points3 today = p;
  today.col(1) += Eigen::Vector3d(0.0, 1e-3, 0.0);
  const MonitorCheck moved = check_monitors(p, today, sd);
  EXPECT_EQ(moved.verdict, MonitorVerdict::kOutlier) << moved.message;
  ASSERT_TRUE(moved.outlier);
  EXPECT_EQ(*moved.outlier, 1);
}

TEST(MonitorCheck, ANonRigidChangeIsNotCalledABump) {
  // Five points; the robot grows by 4e-4 about its base at the sensor's (2, 0, 0): up to 0.4 mm.
  Points3 p(3, 5);
  p << 2.1, 2.6, 2.3, 3.0, 2.0,   //
      -0.4, 0.1, 0.5, -0.2, 0.6,  //
      0.2, 0.3, 0.9, 0.1, 0.5;
  const Eigen::Vector3d base(2.0, 0.0, 0.0);
  const Points3 today = p + 4e-4 * (p.colwise() - base);
  const MonitorCheck c = check_monitors(p, today, Eigen::VectorXd::Constant(5, 2e-5));
  EXPECT_EQ(c.verdict, MonitorVerdict::kSmoothChange) << c.message;
  EXPECT_THROW(check_monitors(p, today.leftCols(4), Eigen::VectorXd::Constant(5, 2e-5)),
               InputError);
}

}  // namespace
}  // namespace vrreg
