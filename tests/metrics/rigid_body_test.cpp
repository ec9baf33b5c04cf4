// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/rigid_body.hpp"

#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

// Brute force: every L_ij stored, two-pass mean and variance in long double.
struct Reference {
  long double mean, sigma, min, max;
  std::vector<double> values;
};
Reference brute_force(const Points3& x, const Points3& y) {
  Reference r{};
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    for (Eigen::Index j = i + 1; j < x.cols(); ++j) {
      r.values.push_back((x.col(i) - x.col(j)).norm() - (y.col(i) - y.col(j)).norm());
    }
  }
  long double sum = 0;
  for (double v : r.values) sum += v;
  r.mean = sum / r.values.size();
  long double ss = 0;
  for (double v : r.values) ss += (v - r.mean) * (v - r.mean);
  r.sigma = std::sqrt(ss / (r.values.size() - 1));
  r.min = *std::min_element(r.values.begin(), r.values.end());
  r.max = *std::max_element(r.values.begin(), r.values.end());
  return r;
}

TEST(RigidBody, MatchesBruteForceReference) {
  Random rng(41);
  for (int n : {2, 3, 17, 400, 1001}) {
    const Points3 x = testing::random_points(rng, n, 0.15, Eigen::Vector3d(0.4, 1.0, 2.0));
    Points3 y = testing::random_transform(rng, 1.0).apply_all(x);
    for (Eigen::Index j = 0; j < y.cols(); ++j) y.col(j) += rng.normal3(0.4e-3);
    const RigidBodyStatistics s = rigid_body_statistics(x, y);
    const Reference ref = brute_force(x, y);
    EXPECT_EQ(s.pairs, static_cast<std::int64_t>(n) * (n - 1) / 2);
    EXPECT_NEAR(s.mean_m, static_cast<double>(ref.mean), 1e-15);
    if (n > 2) {
      EXPECT_NEAR(s.sigma_l_m / static_cast<double>(ref.sigma), 1.0, 1e-10) << n;
    }
    EXPECT_EQ(s.min_m, static_cast<double>(ref.min));
    EXPECT_EQ(s.max_m, static_cast<double>(ref.max));
  }
}

TEST(RigidBody, ZeroForRigidDataAndInvariantToRigidMotion) {
  Random rng(42);
  const Points3 x = testing::random_points(rng, 300, 0.2);
  const Points3 y = testing::random_transform(rng, 2.0).apply_all(x);
  const RigidBodyStatistics s = rigid_body_statistics(x, y);
  EXPECT_LT(s.sigma_l_m, 1e-15);
  EXPECT_LT(std::abs(s.max_m), 1e-15);

  Points3 noisy = y;
  for (Eigen::Index j = 0; j < noisy.cols(); ++j) noisy.col(j) += rng.normal3(1e-3);
  const RigidBodyStatistics a = rigid_body_statistics(x, noisy);
  const RigidBodyStatistics b =
      rigid_body_statistics(testing::random_transform(rng, 1.0).apply_all(x), noisy);
  EXPECT_NEAR(a.sigma_l_m, b.sigma_l_m, 1e-15);
}

TEST(RigidBody, SameInputSameBits) {
  Random rng(43);
  const Points3 x = testing::random_points(rng, 2000, 0.2);
  Points3 y = x;
  for (Eigen::Index j = 0; j < y.cols(); ++j) y.col(j) += rng.normal3(1e-3);
  const RigidBodyStatistics a = rigid_body_statistics(x, y);
  for (int k = 0; k < 3; ++k) {
    const RigidBodyStatistics b = rigid_body_statistics(x, y);
    EXPECT_EQ(a.sigma_l_m, b.sigma_l_m);
    EXPECT_EQ(a.mean_m, b.mean_m);
  }
}

// For independent Gaussian noise of sigma per axis on both sets, L_ij ~ N(0, 2 sigma^2) in the
// limit of large distances (projection of the noise difference on the pair direction, twice).
TEST(RigidBody, GaussianNoiseGivesTwoSigma) {
  Random rng(44);
  const Points3 x0 = testing::random_points(rng, 1500, 0.5);
  const double sigma = 0.1e-3;
  Points3 x = x0, y = x0;
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    x.col(j) += rng.normal3(sigma);
    y.col(j) += rng.normal3(sigma);
  }
  // Pairs share points, so the estimate is correlated; 3 % is still many standard errors.
  EXPECT_NEAR(rigid_body_statistics(x, y).sigma_l_m / (2.0 * sigma), 1.0, 0.03);
}

TEST(RigidBody, HistogramCountsEveryPairOnce) {
  Random rng(45);
  const Points3 x = testing::random_points(rng, 257, 0.2);
  Points3 y = x;
  for (Eigen::Index j = 0; j < y.cols(); ++j) y.col(j) += rng.normal3(1e-3);
  const Histogram h = rigid_body_histogram(x, y, 40, -4e-3, 4e-3);
  const Reference ref = brute_force(x, y);
  std::int64_t total = h.below + h.above;
  for (auto c : h.counts) total += c;
  EXPECT_EQ(total, static_cast<std::int64_t>(ref.values.size()));
  std::vector<std::int64_t> expected(40, 0);
  std::int64_t below = 0, above = 0;
  for (double v : ref.values) {
    const double bin = std::floor((v + 4e-3) / (8e-3 / 40));
    if (v < -4e-3) ++below;
    else if (bin >= 40) ++above;
    else ++expected[static_cast<std::size_t>(bin)];
  }
  EXPECT_EQ(h.counts, expected);
  EXPECT_EQ(h.below, below);
  EXPECT_EQ(h.above, above);
}

TEST(RigidBody, RejectsBadInput) {
  Points3 one(3, 1);
  one.setZero();
  EXPECT_THROW(rigid_body_statistics(one, one), InputError);
  Points3 two = Points3::Zero(3, 2);
  EXPECT_THROW(rigid_body_statistics(two, Points3::Zero(3, 3)), InputError);
  EXPECT_THROW(rigid_body_histogram(two, two, 0, 0.0, 1.0), InputError);
  EXPECT_THROW(rigid_body_histogram(two, two, 5, 1.0, 1.0), InputError);
}

}  // namespace
}  // namespace vrreg
