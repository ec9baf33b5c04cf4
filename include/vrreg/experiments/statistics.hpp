// SPDX-License-Identifier: Apache-2.0
#pragma once
// Small statistics for the reproduction: mean and standard deviation over seeds, and Spearman's
// rank correlation (the "corrected RMS_T falls as d falls" finding of section 5.1, Figure 7).
#include <vector>

namespace vrreg::experiments {

/// Mean and sample standard deviation (divides by n - 1; 0 for n < 2) of n values.
struct MeanSd {
  double mean = 0.0;
  double sd = 0.0;
  int n = 0;
};

/// Mean and sample standard deviation of `values` (summed in the given order); n = 0 for none.
MeanSd mean_sd(const std::vector<double>& values);

/// Ranks 1..n of `values`, ties taking the average of the ranks they span.
std::vector<double> average_ranks(const std::vector<double>& values);

/// Spearman's rho: Pearson's correlation of the average ranks of x and y (same length >= 2).
/// NaN when either has all values equal. Throws InputError on different lengths or n < 2.
double spearman_rank_correlation(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace vrreg::experiments
