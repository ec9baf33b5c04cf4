// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/local_rms.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"

namespace vrreg {
namespace {

// The second method: every distance, sorted.
double brute_force_local_rms(const Points3& points_m, const Eigen::VectorXd& squared_m2,
                             const Eigen::Vector3d& query_m, std::size_t k) {
  std::vector<std::pair<double, Eigen::Index>> by_distance;
  for (Eigen::Index j = 0; j < points_m.cols(); ++j) {
    if (std::isnan(squared_m2(j))) continue;
    by_distance.emplace_back((points_m.col(j) - query_m).squaredNorm(), j);
  }
  std::sort(by_distance.begin(), by_distance.end());
  k = std::min(k, by_distance.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < k; ++i) sum += squared_m2(by_distance[i].second);
  return std::sqrt(sum / static_cast<double>(k));
}

TEST(LocalRms, MatchesEveryDistanceSortedAndSkipsUnknownErrors) {
  Random rng(17);
  const Eigen::Index n = 300;
  Points3 points_m(3, n);
  Eigen::VectorXd squared_m2(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    points_m.col(j) = Eigen::Vector3d(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2),
                                      rng.uniform(0.0, 0.3));
    // Larger errors towards +x, as at an edge the model extrapolates to.
    squared_m2(j) = std::pow(1e-4 * (1.5 + points_m(0, j) / 0.2), 2) * rng.uniform(0.5, 1.5);
    if (j % 37 == 0) squared_m2(j) = std::numeric_limits<double>::quiet_NaN();
  }
  Points3 queries_m(3, 60);
  for (Eigen::Index q = 0; q < queries_m.cols(); ++q) {
    queries_m.col(q) = Eigen::Vector3d(rng.uniform(-0.25, 0.25), rng.uniform(-0.25, 0.25),
                                       rng.uniform(-0.05, 0.35));
  }
  for (const int k : {1, 16, 1000}) {
    const Eigen::VectorXd got = local_rms(points_m, squared_m2, queries_m, k);
    ASSERT_EQ(got.size(), queries_m.cols());
    for (Eigen::Index q = 0; q < queries_m.cols(); ++q) {
      const double want = brute_force_local_rms(points_m, squared_m2, queries_m.col(q),
                                                static_cast<std::size_t>(k));
      EXPECT_NEAR(got(q), want, 1e-13 * want) << "k " << k << " query " << q;
    }
  }
  // k above the known count: the RMS of every known error, the same everywhere.
  double sum = 0.0;
  int known = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!std::isnan(squared_m2(j))) sum += squared_m2(j), ++known;
  }
  const Eigen::VectorXd all = local_rms(points_m, squared_m2, queries_m, 1000);
  EXPECT_NEAR(all.minCoeff(), std::sqrt(sum / known), 1e-15);
  EXPECT_NEAR(all.maxCoeff(), std::sqrt(sum / known), 1e-15);
  // At a point with a known error and k = 1: that error.
  const Eigen::VectorXd own = local_rms(points_m, squared_m2, points_m.leftCols(5), 1);
  for (Eigen::Index j = 1; j < 5; ++j) EXPECT_DOUBLE_EQ(own(j), std::sqrt(squared_m2(j)));
  // The +x side, with its larger errors, gets the larger local RMS.
  Points3 sides_m(3, 2);
  sides_m << -0.18, 0.18, 0.0, 0.0, 0.15, 0.15;
  const Eigen::VectorXd sides = local_rms(points_m, squared_m2, sides_m, 16);
  EXPECT_GT(sides(1), 1.5 * sides(0));
}

TEST(LocalRms, RefusesWhatItCannotAnswer) {
  Points3 points_m = Points3::Random(3, 4);
  const Eigen::VectorXd squared_m2 = Eigen::VectorXd::Constant(4, 1e-8);
  EXPECT_THROW((void)local_rms(points_m, squared_m2, points_m, 0), InputError);
  EXPECT_THROW((void)local_rms(points_m, Eigen::VectorXd::Constant(3, 1e-8), points_m, 2),
               InputError);
  EXPECT_THROW((void)local_rms(points_m,
                               Eigen::VectorXd::Constant(4, std::numeric_limits<double>::quiet_NaN()),
                               points_m, 2),
               InputError);
  EXPECT_EQ(local_rms(points_m, squared_m2, Points3(3, 0), 2).size(), 0);
}

}  // namespace
}  // namespace vrreg
