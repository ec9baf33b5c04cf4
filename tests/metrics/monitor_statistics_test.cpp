// SPDX-License-Identifier: Apache-2.0
// The monitor check's statistics by Monte Carlo against their stated distributions: the sensor's
// move and its covariance stated at the same point (error/sd chi-distributed, at the origin 2 m
// away as at the monitors), one or two points testing a translation, today's noise against the
// registration's at the stated rate, and a change that came at once told from one that grew.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "vrreg/core/random.hpp"
#include "vrreg/metrics/distributions.hpp"
#include "vrreg/metrics/monitor_check.hpp"
#include "vrreg_test.hpp"

namespace vrreg::monitor_statistics_test {
namespace {

// Four monitor points 2.1-2.6 m from the tracker, over ~0.5 m, not on one plane.
Points3 four_monitors() {
  Points3 p(3, 4);
  p << 2.1, 2.6, 2.3, 2.4,   //
      -0.2, 0.1, 0.3, -0.1,  //
      0.2, 0.3, 0.1, 0.6;
  return p;
}

// Three binomial sd of a rate estimated from `runs` draws.
double three_sd(double rate, int runs) { return 3.0 * std::sqrt(rate * (1.0 - rate) / runs); }

TEST(RigidChangeCovariance, TheMoveAndItsCovarianceAreStatedAtTheSamePoint) {
  Random rng(41);
  const Points3 p = four_monitors();
  const double sigma = 2e-5;  // per reading and axis, then and today
  const Eigen::VectorXd sd = Eigen::VectorXd::Constant(4, std::sqrt(2.0) * sigma);
  const int runs = 400;
  double origin6 = 0.0, origin_t = 0.0, centroid_t = 0.0, wrong_t = 0.0;
  int above = 0;
  const double bound6 = chi_square_quantile_upper(0.01, 6);
  for (int r = 0; r < runs; ++r) {
    // A bump: a turn about a random axis (~0.1 mrad) and a 0.1 mm shift of the points' centre,
    // always found; its translation t is the origin's, 2 m from them.
    const Eigen::Vector3d omega = 5e-5 * rng.normal3(1.0);
    const Eigen::Vector3d t =
        1e-4 * rng.normal3(1.0).normalized() - omega.cross(Eigen::Vector3d(p.rowwise().mean()));
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix();
    Points3 before = p, after = p;
    for (Eigen::Index i = 0; i < 4; ++i) {
      before.col(i) += rng.normal3(sigma);
      after.col(i) = R * p.col(i) + t + rng.normal3(sigma);
    }
    const MonitorCheck c = check_monitors(before, after, sd);
    ASSERT_TRUE(c.rigid) << c.message;
    const RigidChange& m = *c.rigid;
    EXPECT_EQ(m.rotation_rank, 3);
    Eigen::Matrix<double, 6, 1> e;
    e << m.rotation_rad - omega, m.translation_m - t;
    const double q = e.dot(m.covariance.ldlt().solve(e));
    origin6 += q / runs;
    above += q > bound6 ? 1 : 0;
    const Eigen::Vector3d et = m.translation_m - t;
    origin_t += et.dot(m.covariance.bottomRightCorner<3, 3>().ldlt().solve(et)) / runs;
    // The centroid moves by t + omega x c.
    const Eigen::Vector3d ec = m.translation_at_centroid_m - (t + omega.cross(m.centroid_m));
    centroid_t +=
        ec.dot(m.covariance_at_centroid.bottomRightCorner<3, 3>().ldlt().solve(ec)) / runs;
    // The origin's move against the centroid's covariance: what the two points mixed gave.
    wrong_t += et.dot(m.covariance_at_centroid.bottomRightCorner<3, 3>().ldlt().solve(et)) / runs;
  }
  std::printf(
      "error' cov^-1 error over %d bumps: (omega, t at the origin) %.2f (chi2_6: 6), "
      "t at the origin %.2f, at the centroid %.2f (chi2_3: 3); t at the origin with the "
      "centroid's covariance %.0f; above chi2_6's 99 %% bound %d\n",
      runs, origin6, origin_t, centroid_t, wrong_t, above);
  // Means of chi2_6 and chi2_3 over 400 draws: sd 0.17 and 0.12.
  EXPECT_NEAR(origin6, 6.0, 0.7);
  EXPECT_NEAR(origin_t, 3.0, 0.5);
  EXPECT_NEAR(centroid_t, 3.0, 0.5);
  EXPECT_GT(wrong_t, 30.0);
  EXPECT_LE(above, 12);  // 4 expected
}

TEST(FewMonitors, OneOrTwoPointsTestATranslationAtTheStatedRate) {
  Random rng(43);
  const Points3 p = four_monitors();
  const int runs = testing::sanitized() ? 2000 : 20000;
  for (const int n : {1, 2}) {
    const Points3 q = p.leftCols(n);
    const Eigen::VectorXd sd = Eigen::VectorXd::Constant(n, 2e-5);
    int alarms = 0, rigid = 0, detected = 0;
    for (int r = 0; r < runs; ++r) {
      Points3 today = q;
      for (Eigen::Index i = 0; i < n; ++i) today.col(i) += rng.normal3(2e-5);
      alarms += check_monitors(q, today, sd).verdict != MonitorVerdict::kValid ? 1 : 0;
      if (r % 10 != 0) continue;
      // A pure 0.1 mm translation.
      today.colwise() += 1e-4 * rng.normal3(1.0).normalized();
      const MonitorCheck c = check_monitors(q, today, sd);
      detected += c.verdict != MonitorVerdict::kValid ? 1 : 0;
      rigid += c.verdict == MonitorVerdict::kRigidChange ? 1 : 0;
    }
    const double rate = static_cast<double>(alarms) / runs;
    std::printf(
        "%d monitor point(s): false alarms %.4f (stated 0.01); a 0.1 mm translation found "
        "%d, called rigid %d of %d\n",
        n, rate, detected, rigid, runs / 10);
    EXPECT_NEAR(rate, 0.01, three_sd(0.01, runs));
    EXPECT_GE(detected, 0.95 * runs / 10);
    // Not rigid only when the rest's test (the distance of two points) alarms falsely.
    EXPECT_GE(rigid, detected - (0.01 + three_sd(0.01, runs / 10)) * runs / 10);
  }
  // Two points: the distance between them changing is not rigid; their turn and shift is.
  const Points3 two = p.leftCols(2);
  Points3 stretched = two;
  stretched.col(1) += 3e-4 * (two.col(1) - two.col(0)).normalized();
  const Eigen::VectorXd sd2 = Eigen::VectorXd::Constant(2, 2e-5);
  EXPECT_NE(check_monitors(two, stretched, sd2).verdict, MonitorVerdict::kRigidChange);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(2e-4, Eigen::Vector3d(0.3, 1, 0.2).normalized()).toRotationMatrix();
  const MonitorCheck turned = check_monitors(two, R * two, sd2);
  EXPECT_EQ(turned.verdict, MonitorVerdict::kRigidChange) << turned.message;
  EXPECT_EQ(turned.rigid->rotation_rank, 2);
  EXPECT_EQ(turned.rigid_dof, 5);
  // What each layout cannot tell.
  EXPECT_EQ(monitor_blind_spots(p.leftCols(1)).size(), 1u);
  EXPECT_NE(monitor_blind_spots(two).front().find("line"), std::string::npos);
  EXPECT_NE(monitor_blind_spots(p.leftCols(3)).front().find("plane"), std::string::npos);
  EXPECT_TRUE(monitor_blind_spots(p).empty());
}

TEST(VisitNoise, TodayNoisierIsFoundAtTheStatedRate) {
  Random rng(47);
  const int runs = testing::sanitized() ? 2000 : 20000;
  // 4 points: 12 visits at registration (132 dof), 4 today (36 dof).
  const double nu_then = 132, nu_today = 36;
  const auto variance = [&rng](double sigma, double nu) {
    double ss = 0.0;
    for (int k = 0; k < static_cast<int>(nu); ++k) ss += std::pow(rng.normal(sigma), 2);
    return ss / nu;
  };
  int same = 0, twice = 0, known = 0;
  for (int r = 0; r < runs; ++r) {
    const double then = variance(2e-5, nu_then);
    same += compare_visit_noise(then, nu_then, variance(2e-5, nu_today), nu_today, 0.01).noisier;
    twice += compare_visit_noise(then, nu_then, variance(4e-5, nu_today), nu_today, 0.01).noisier;
    known += compare_visit_noise(4e-10, 0.0, variance(2e-5, nu_today), nu_today, 0.01).noisier;
  }
  std::printf(
      "today noisier, same noise: %.4f (F), %.4f (known sd), stated 0.01; twice the sd: "
      "%.4f\n",
      double(same) / runs, double(known) / runs, double(twice) / runs);
  EXPECT_NEAR(double(same) / runs, 0.01, three_sd(0.01, runs));
  EXPECT_NEAR(double(known) / runs, 0.01, three_sd(0.01, runs));
  EXPECT_GT(double(twice) / runs, 0.99);
  const VisitNoiseComparison once = compare_visit_noise(4e-10, 30, 9e-10, 0, 0.01);
  EXPECT_FALSE(once.tested);
  EXPECT_FALSE(once.noisier);
  EXPECT_THROW(compare_visit_noise(0.0, 1, 1e-10, 1, 0.01), InputError);
}

// Checks every 2 min of 4 points (sd of a check's mean `sd` per axis), today's change of a size
// that just alarms; earlier fractions of it `phi(t)`.
struct OnsetCase {
  int earlier = 5;
  double sd_m = 1.4e-5;
  double chi2_today = 30.0;  // |Delta|^2 / (2 sd^2): a first alarm
};

template <typename Fraction>
ChangeOnsetTest onset_of(Random& rng, const OnsetCase& c, Fraction phi) {
  const int n = 4;
  Eigen::VectorXd delta(3 * n);
  for (int i = 0; i < 3 * n; ++i) delta(i) = rng.normal();
  delta *= std::sqrt(2.0 * c.chi2_today) * c.sd_m / delta.norm();
  // Every check is read against the same registration: its noise is in all the differences.
  Eigen::VectorXd baseline(3 * n);
  for (int i = 0; i < 3 * n; ++i) baseline(i) = rng.normal(c.sd_m);
  // A check found the change when it was whole there (a step seen at once).
  const auto check_at = [&](double fraction, double t_s) {
    MonitorReadings m{Points3(3, n), Eigen::VectorXd::Constant(n, c.sd_m), t_s, fraction >= 1.0};
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a)
        m.difference_m(a, i) =
            fraction * delta(3 * i + a) + rng.normal(c.sd_m) - baseline(3 * i + a);
    return m;
  };
  std::vector<MonitorReadings> earlier;
  const double today_s = 120.0 * (c.earlier + 1);
  for (int k = 1; k <= c.earlier; ++k)
    earlier.push_back(check_at(phi(120.0 * k, today_s), 120.0 * k));
  return classify_change_onset(Eigen::VectorXd::Constant(n, c.sd_m), earlier,
                               check_at(1.0, today_s), 0.01);
}

TEST(ChangeOnset, AStepIsABumpAndAWarmUpARamp) {
  Random rng(53);
  const int runs = testing::sanitized() ? 300 : 3000;
  const OnsetCase c;
  int fresh = 0, earlier_step = 0, warm = 0, warm10 = 0;
  // A warm-up: 1 - exp(-t / 30 min), today's change its whole.
  const auto warm_up = [](double t, double today) {
    return std::expm1(-t / 1800.0) / std::expm1(-today / 1800.0);
  };
  for (int r = 0; r < runs; ++r) {
    // A bump since the last check; one the earlier checks already show (after the 3rd).
    fresh += onset_of(rng, c, [](double, double) { return 0.0; }).onset == ChangeOnset::kRamp;
    earlier_step += onset_of(rng, c, [](double t, double) {
                      return t > 360.0 ? 1.0 : 0.0;
                    }).onset == ChangeOnset::kRamp;
    warm += onset_of(rng, c, warm_up).onset == ChangeOnset::kRamp;
    OnsetCase ten = c;
    ten.earlier = 10;
    warm10 += onset_of(rng, ten, warm_up).onset == ChangeOnset::kRamp;
  }
  const auto rate = [runs](int k) { return static_cast<double>(k) / runs; };
  std::printf(
      "called a ramp: a bump since the last of 5 checks %.4f, a bump the last 2 checks "
      "show %.4f (stated 0.01); a warm-up after 5 checks %.3f, after 10 %.3f\n",
      rate(fresh), rate(earlier_step), rate(warm), rate(warm10));
  EXPECT_LE(rate(fresh), 0.01 + three_sd(0.01, runs));
  EXPECT_LE(rate(earlier_step), 0.02 + three_sd(0.02, runs));
  EXPECT_GT(rate(warm), 0.45);
  EXPECT_GT(rate(warm10), 0.7);
  // Well resolved: a clear ramp and a clear step, the step's place found.
  OnsetCase big = c;
  big.chi2_today = 400.0;
  const ChangeOnsetTest ramp = onset_of(rng, big, warm_up);
  EXPECT_EQ(ramp.onset, ChangeOnset::kRamp);
  ASSERT_EQ(ramp.fractions.size(), 5u);
  EXPECT_NEAR(ramp.fractions[2], warm_up(360.0, 720.0), 0.1);
  const ChangeOnsetTest step =
      onset_of(rng, big, [](double t, double) { return t > 360.0 ? 1.0 : 0.0; });
  EXPECT_EQ(step.onset, ChangeOnset::kStep);
  EXPECT_EQ(step.step_after, 2);  // after the check at 6 min
  // No earlier check: cannot be told.
  OnsetCase none = c;
  none.earlier = 0;
  EXPECT_EQ(onset_of(rng, none, warm_up).onset, ChangeOnset::kUnknown);
}

}  // namespace
}  // namespace vrreg::monitor_statistics_test
