// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "vrreg/core/check.hpp"

namespace vrreg::experiments {

MeanSd mean_sd(const std::vector<double>& values) {
  MeanSd out;
  out.n = static_cast<int>(values.size());
  if (values.empty()) return out;
  double sum = 0.0;
  for (const double v : values) sum += v;
  out.mean = sum / static_cast<double>(values.size());
  if (values.size() < 2) return out;
  double ss = 0.0;
  for (const double v : values) ss += (v - out.mean) * (v - out.mean);
  out.sd = std::sqrt(ss / static_cast<double>(values.size() - 1));
  return out;
}

std::vector<double> average_ranks(const std::vector<double>& values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> ranks(values.size());
  for (std::size_t first = 0; first < order.size();) {
    std::size_t last = first;
    while (last + 1 < order.size() && values[order[last + 1]] == values[order[first]]) ++last;
    const double rank = 0.5 * static_cast<double>(first + last) + 1.0;  // 1-based average
    for (std::size_t k = first; k <= last; ++k) ranks[order[k]] = rank;
    first = last + 1;
  }
  return ranks;
}

double spearman_rank_correlation(const std::vector<double>& x, const std::vector<double>& y) {
  VRREG_THROW_UNLESS(x.size() == y.size(),
                     "Spearman: " << x.size() << " x values but " << y.size() << " y values");
  VRREG_THROW_UNLESS(x.size() >= 2, "Spearman needs at least 2 pairs, got " << x.size());
  const std::vector<double> rx = average_ranks(x);
  const std::vector<double> ry = average_ranks(y);
  const double mx = mean_sd(rx).mean;
  const double my = mean_sd(ry).mean;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t k = 0; k < rx.size(); ++k) {
    sxy += (rx[k] - mx) * (ry[k] - my);
    sxx += (rx[k] - mx) * (rx[k] - mx);
    syy += (ry[k] - my) * (ry[k] - my);
  }
  if (sxx == 0.0 || syy == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return sxy / std::sqrt(sxx * syy);
}

}  // namespace vrreg::experiments
