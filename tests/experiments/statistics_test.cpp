// SPDX-License-Identifier: Apache-2.0
// Mean +- sd over seeds and Spearman's rank correlation, against values worked out by hand.
#include "vrreg/experiments/statistics.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg::experiments {
namespace {

TEST(MeanSd, HandValues) {
  const MeanSd m = mean_sd({2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0});
  EXPECT_EQ(m.n, 8);
  EXPECT_DOUBLE_EQ(m.mean, 5.0);
  EXPECT_DOUBLE_EQ(m.sd, std::sqrt(32.0 / 7.0));  // squared deviations sum to 32, n - 1 = 7
  const MeanSd one = mean_sd({3.5});
  EXPECT_DOUBLE_EQ(one.mean, 3.5);
  EXPECT_DOUBLE_EQ(one.sd, 0.0);
  EXPECT_EQ(mean_sd({}).n, 0);
}

TEST(Spearman, RanksAverageTies) {
  EXPECT_EQ(average_ranks({10.0, 30.0, 20.0, 20.0}), (std::vector<double>{1.0, 4.0, 2.5, 2.5}));
}

TEST(Spearman, MonotoneIsOneAndReversedIsMinusOne) {
  const std::vector<double> d = {43.3, 39.0, 34.6, 30.3, 26.0};
  EXPECT_DOUBLE_EQ(spearman_rank_correlation(d, {0.24, 0.22, 0.21, 0.2, 0.19}), 1.0);
  EXPECT_DOUBLE_EQ(spearman_rank_correlation(d, {0.1, 0.2, 0.3, 0.4, 0.5}), -1.0);
}

TEST(Spearman, OneSwapOfFive) {
  // Ranks 1..5 against 1, 2, 4, 3, 5: sum d^2 = 2, rho = 1 - 6 * 2 / (5 * 24) = 0.9.
  EXPECT_NEAR(spearman_rank_correlation({1, 2, 3, 4, 5}, {10, 20, 40, 30, 50}), 0.9, 1e-15);
}

TEST(Spearman, TiesUsePearsonOnAverageRanks) {
  // y ranks 1.5, 1.5, 3, 4 against x ranks 1..4: Pearson = 4.5 / sqrt(5 * 4.5).
  EXPECT_NEAR(spearman_rank_correlation({1, 2, 3, 4}, {7, 7, 8, 9}), 4.5 / std::sqrt(22.5), 1e-15);
  EXPECT_TRUE(std::isnan(spearman_rank_correlation({1, 2, 3}, {5, 5, 5})));
  EXPECT_THROW(spearman_rank_correlation({1, 2}, {1, 2, 3}), InputError);
  EXPECT_THROW(spearman_rank_correlation({1}, {1}), InputError);
}

}  // namespace
}  // namespace vrreg::experiments
