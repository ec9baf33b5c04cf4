// SPDX-License-Identifier: Apache-2.0
// The LOO outlier check against closed forms: chi-square quantiles, exact affine prediction,
// the variance factor of a symmetric neighbourhood, the false-alarm rate under Gaussian noise.
#include "vrreg/correction/outliers.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "correction_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::grid_points;

// An affine correction field eps = A Y + b [m] at the points.
Points3 affine_field(const Points3& robot_m) {
  Eigen::Matrix3d a;
  a << 1e-3, -2e-3, 0.5e-3, 3e-3, 0.2e-3, -1e-3, -0.7e-3, 1.5e-3, 2e-3;
  return (a * robot_m).colwise() + Eigen::Vector3d(0.4e-3, -0.2e-3, 1e-3);
}

TEST(ChiSquareBound, MatchesTabulatedQuantiles) {
  // chi2_3 upper quantiles (one test): 0.05 -> 7.814728, 0.01 -> 11.344867, 0.001 -> 16.266236.
  EXPECT_NEAR(chi_square3_family_bound(0.05, 1), 7.814728, 1e-5);
  EXPECT_NEAR(chi_square3_family_bound(0.01, 1), 11.344867, 1e-5);
  EXPECT_NEAR(chi_square3_family_bound(0.001, 1), 16.266236, 1e-5);
  // Sidak over J tests: 1 - (1 - 0.01)^(1/1000) = 1.00503e-5 per test -> a per-test 1e-5 quantile
  // (tabulated 25.9017) lies just above it.
  EXPECT_NEAR(chi_square3_family_bound(0.01, 1000), 25.8916, 2e-3);
  EXPECT_THROW((void)chi_square3_family_bound(0.0, 10), InputError);
}

TEST(DetectOutlierFiducials, AffineFieldHasNoOutliersAndEveryDeviationIsZero) {
  const Points3 y = grid_points(6, 5, 4, Eigen::Vector3d(0.025, 0.03, 0.02));
  const OutlierDetection d = detect_outlier_fiducials(y, affine_field(y), {}, 50e-6);
  ASSERT_TRUE(d.converged);
  EXPECT_TRUE(d.outliers.empty());
  EXPECT_EQ(d.n_judged, 120);
  EXPECT_LT(d.sigma_spread_m, 1e-15);
  EXPECT_TRUE(d.scale_is_noise);
  EXPECT_DOUBLE_EQ(d.sigma_m, 50e-6);
  EXPECT_NEAR(d.threshold_sigmas, std::sqrt(chi_square3_family_bound(0.01, 120)), 1e-12);
}

TEST(DetectOutlierFiducials, DisplacedCentreOfASymmetricBlockClosedForm) {
  // Centre of a 7^3 lattice: its 26 nearest form the 3x3x3 block, whose affine fit at the centre
  // is the plain mean (symmetric design): w = 1/26, deviation = d exactly, sigmas =
  // |d| / (sigma sqrt(1 + 1/26)); the fill is the affine value.
  const Points3 y = grid_points(7, 7, 7, Eigen::Vector3d::Constant(0.025));
  const Points3 clean = affine_field(y);
  Points3 eps = clean;
  const Eigen::Index centre = 3 + 7 * (3 + 7 * 3);
  const Eigen::Vector3d d(0.3e-3, -0.4e-3, 0.0);
  eps.col(centre) += d;
  const double sigma = 40e-6;
  const OutlierDetection r = detect_outlier_fiducials(y, eps, {}, sigma);
  ASSERT_TRUE(r.converged);
  ASSERT_EQ(r.outliers.size(), 1u);
  const FiducialOutlier& o = r.outliers[0];
  EXPECT_EQ(o.fiducial, centre);
  EXPECT_EIGEN_NEAR(o.deviation_sensor_m, d, 1e-15);
  EXPECT_NEAR(o.sigmas, d.norm() / (sigma * std::sqrt(1.0 + 1.0 / 26.0)), 1e-9);
  ASSERT_EQ(o.fill_weights.size(), 26u);
  for (const double w : o.fill_weights) EXPECT_NEAR(w, 1.0 / 26.0, 1e-12);
  EXPECT_EIGEN_NEAR(o.fill(eps), clean.col(centre), 1e-15);
}

TEST(DetectOutlierFiducials, DeviationsDoNotDependOnTheRegistration) {
  // A different {R, tau} adds an affine field to every correction (Eq. 6): same verdicts.
  Random rng(5);
  const Points3 y = grid_points(6, 6, 6, Eigen::Vector3d::Constant(0.025));
  Points3 eps(3, y.cols());
  for (Eigen::Index j = 0; j < y.cols(); ++j) eps.col(j) = rng.normal3(30e-6);
  eps.col(40) += Eigen::Vector3d(0.0, 0.0, 0.5e-3);
  const OutlierDetection a = detect_outlier_fiducials(y, eps, {}, 30e-6);
  const OutlierDetection b = detect_outlier_fiducials(y, eps + affine_field(y), {}, 30e-6);
  ASSERT_EQ(a.outliers.size(), 1u);
  ASSERT_EQ(b.outliers.size(), 1u);
  EXPECT_EQ(a.outliers[0].fiducial, 40);
  EXPECT_EQ(b.outliers[0].fiducial, 40);
  EXPECT_EIGEN_NEAR(a.outliers[0].deviation_sensor_m, b.outliers[0].deviation_sensor_m, 1e-12);
  EXPECT_NEAR(a.sigma_spread_m, b.sigma_spread_m, 1e-12);
}

TEST(DetectOutlierFiducials, GaussianNoiseFalseAlarmRateAndSpread) {
  // With eps = affine + N(0, sigma^2) per axis and sigma known, t_j ~ chi2_3: the spread
  // estimates sigma and a clean set loses a fiducial with probability ~ the rate (0.2 here;
  // the t_j are mildly correlated, so a binomial band with some slack).
  const Points3 y = grid_points(6, 6, 6, Eigen::Vector3d::Constant(0.025));
  const double sigma = 50e-6;
  Random rng(11);
  OutlierOptions options;
  options.false_alarm_rate = 0.2;
  int alarms = 0;
  double spread_sum = 0.0;
  constexpr int kTrials = 200;
  for (int trial = 0; trial < kTrials; ++trial) {
    Points3 eps = affine_field(y);
    for (Eigen::Index j = 0; j < y.cols(); ++j) eps.col(j) += rng.normal3(sigma);
    const OutlierDetection d = detect_outlier_fiducials(y, eps, {}, sigma, options);
    alarms += d.outliers.empty() ? 0 : 1;
    spread_sum += d.sigma_spread_m;
  }
  EXPECT_NEAR(spread_sum / kTrials, sigma, 0.05 * sigma);
  EXPECT_GE(alarms, 20);  // 0.2 * 200 = 40, binomial sd 5.7
  EXPECT_LE(alarms, 60);
}

TEST(DetectOutlierFiducials, SwappedPairIsFoundAndNothingElse) {
  Random rng(12);
  const Points3 y = grid_points(8, 7, 6, Eigen::Vector3d::Constant(0.025));
  Points3 eps = affine_field(y);
  for (Eigen::Index j = 0; j < y.cols(); ++j) eps.col(j) += rng.normal3(40e-6);
  // Swapping two sensor readings 25 mm apart: eps_a gets X_a - X_b more, eps_b the opposite.
  const Eigen::Vector3d step(0.025, 0.0, 0.0);
  eps.col(100) += step;
  eps.col(101) -= step;
  const OutlierDetection d = detect_outlier_fiducials(y, eps, {}, 40e-6);
  ASSERT_TRUE(d.converged);
  ASSERT_EQ(d.outliers.size(), 2u);
  EXPECT_EQ(d.outliers[0].fiducial, 100);
  EXPECT_EQ(d.outliers[1].fiducial, 101);
  EXPECT_GT(d.outliers[0].sigmas, 100.0);
}

TEST(DetectOutlierFiducials, NeighboursStayWithinTheirConfiguration) {
  // Two configurations at the same positions with different affine fields: judged apart, no
  // outlier; judged as one group, the fields clash everywhere (a spread far beyond the noise).
  const Points3 one = grid_points(5, 5, 5, Eigen::Vector3d::Constant(0.025));
  Points3 y(3, 250), eps(3, 250);
  y << one, one;
  const Points3 other = (-affine_field(one)).colwise() + Eigen::Vector3d(1e-3, 0.0, 0.0);
  eps << affine_field(one), other;
  std::vector<int> groups(250, 1);
  std::fill(groups.begin() + 125, groups.end(), 2);
  const OutlierDetection apart = detect_outlier_fiducials(y, eps, groups, 40e-6);
  ASSERT_TRUE(apart.converged);
  EXPECT_TRUE(apart.outliers.empty());
  const OutlierDetection mixed = detect_outlier_fiducials(y, eps, {}, 40e-6);
  EXPECT_TRUE(apart.scale_is_noise);
  EXPECT_FALSE(mixed.scale_is_noise);
  EXPECT_GT(mixed.sigma_spread_m, 10 * 40e-6);
}

TEST(DetectOutlierFiducials, TooFewNeighboursJudgesNothing) {
  const Points3 y = grid_points(2, 2, 1, Eigen::Vector3d::Constant(0.025));
  Points3 eps = affine_field(y);
  eps.col(0) += Eigen::Vector3d(1e-3, 0.0, 0.0);
  const OutlierDetection d = detect_outlier_fiducials(y, eps, {}, 40e-6);
  EXPECT_TRUE(d.converged);
  EXPECT_EQ(d.n_judged, 0);
  EXPECT_TRUE(d.outliers.empty());
}

TEST(DetectOutlierFiducials, ReportsAnUnusableSet) {
  Random rng(13);
  const Points3 y = grid_points(6, 6, 6, Eigen::Vector3d::Constant(0.025));
  Points3 eps = affine_field(y);
  for (Eigen::Index j = 0; j < y.cols(); j += 2) eps.col(j) += rng.normal3(5e-3);
  const OutlierDetection d = detect_outlier_fiducials(y, eps, {}, 40e-6);
  EXPECT_FALSE(d.converged);
  EXPECT_NE(d.message.find("disagree with their neighbours"), std::string::npos);
}

TEST(DetectOutlierFiducials, RejectsBadInput) {
  const Points3 y = grid_points(3, 3, 3, Eigen::Vector3d::Constant(0.025));
  EXPECT_THROW((void)detect_outlier_fiducials(y, Points3::Zero(3, 5), {}, {}), InputError);
  EXPECT_THROW((void)detect_outlier_fiducials(y, affine_field(y), {1, 2}, {}), InputError);
  OutlierOptions bad;
  bad.false_alarm_rate = 1.5;
  EXPECT_THROW((void)detect_outlier_fiducials(y, affine_field(y), {}, {}, bad), InputError);
}

}  // namespace
}  // namespace vrreg
