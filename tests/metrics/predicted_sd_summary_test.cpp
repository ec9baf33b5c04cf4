// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cmath>

#include "vrreg/metrics/uncertainty_calibration.hpp"

namespace vrreg {
namespace {

// NaN (uncorrected points) is left out; an even count takes the mean of the middle two.
TEST(PredictedSdSummary, MedianAndMaxOfTheFiniteValues) {
  Eigen::VectorXd sd(5);
  sd << 3.0, std::nan(""), 1.0, 4.0, 2.0;
  const PredictedSdSummary s = summarize_predicted_sd(sd);
  EXPECT_EQ(s.n, 4);
  EXPECT_EQ(s.median_m, 2.5);
  EXPECT_EQ(s.max_m, 4.0);
  EXPECT_EQ(summarize_predicted_sd(Eigen::VectorXd()).n, 0);
}

}  // namespace
}  // namespace vrreg
