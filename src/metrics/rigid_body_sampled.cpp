// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/rigid_body_sampled.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "vrreg/core/check.hpp"
#include "vrreg/core/progress.hpp"
#include "vrreg/core/random.hpp"

namespace vrreg {
namespace {

// Power sums of d = L - shift (shift: one L of the set, so that the sums stay small).
struct Moments {
  std::int64_t n = 0;
  double s1 = 0.0, s2 = 0.0, s3 = 0.0, s4 = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
};

Moments combine(Moments a, const Moments& b) {
  a.n += b.n;
  a.s1 += b.s1;
  a.s2 += b.s2;
  a.s3 += b.s3;
  a.s4 += b.s4;
  a.min = std::min(a.min, b.min);
  a.max = std::max(a.max, b.max);
  return a;
}

double pair_l(const ConstPoints3Ref& x, const ConstPoints3Ref& y, Eigen::Index i, Eigen::Index j) {
  return (x.col(i) - x.col(j)).norm() - (y.col(i) - y.col(j)).norm();
}

// Pairs per chunk: each chunk draws from its own stream, so the result does not depend on threads.
constexpr std::int64_t kChunkPairs = 1 << 16;
constexpr double kZ95 = 1.959963984540054;  // two-sided 95 % normal quantile

void check_sample_input(const ConstPoints3Ref& x, const ConstPoints3Ref& y, std::int64_t pairs) {
  VRREG_THROW_UNLESS(x.cols() == y.cols(), "rigid-body condition needs corresponding points: "
                                               << x.cols() << " vs " << y.cols());
  VRREG_THROW_UNLESS(x.cols() >= 2, "rigid-body condition needs at least 2 points");
  VRREG_THROW_UNLESS(pairs >= 2, "sigma_L sampling needs at least 2 pairs, got " << pairs);
  VRREG_THROW_UNLESS(x.allFinite() && y.allFinite(), "rigid-body condition: non-finite point");
}

// Reduces add(acc, L) over `pairs` pairs (i != j) drawn uniformly with `seed`: the same pairs for
// the statistics and the histogram, in fixed chunks reduced in a fixed order.
// 10^7 pairs take about a second: each chunk is a step of the progress.
template <class Acc, class Add, class Combine>
Acc reduce_sampled_pairs(const ConstPoints3Ref& x, const ConstPoints3Ref& y, std::int64_t pairs,
                         std::uint64_t seed, const Acc& empty, Add add, Combine combine) {
  const auto j = static_cast<std::uint64_t>(x.cols());
  const std::int64_t chunks = (pairs + kChunkPairs - 1) / kChunkPairs;
  ProgressStage progress("sigma_L over " + std::to_string(pairs) + " sampled pairs", chunks);
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::int64_t>(0, chunks, 1), empty,
      [&](const tbb::blocked_range<std::int64_t>& range, Acc acc) {
        for (std::int64_t c = range.begin(); c < range.end(); ++c) {
          Random random = Random::stream(seed, static_cast<std::uint64_t>(c));
          const std::int64_t n = std::min(kChunkPairs, pairs - c * kChunkPairs);
          for (std::int64_t k = 0; k < n; ++k) {
            // Uniform over ordered pairs a != b, hence over unordered pairs.
            const std::uint64_t a = random.below(j);
            std::uint64_t b = random.below(j - 1);
            if (b >= a) ++b;
            add(acc, pair_l(x, y, static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)));
          }
          progress.advance();
        }
        return acc;
      },
      combine);
}

}  // namespace

void SigmaLOptions::validate() const {
  VRREG_THROW_UNLESS(sample_pairs >= 2,
                     "sigma_L sampling needs at least 2 pairs, got " << sample_pairs);
}

RigidBodyEstimate rigid_body_statistics_sampled(const ConstPoints3Ref& points_sensor_m,
                                                const ConstPoints3Ref& points_robot_m,
                                                std::int64_t pairs, std::uint64_t seed) {
  check_sample_input(points_sensor_m, points_robot_m, pairs);
  const auto j = static_cast<std::uint64_t>(points_sensor_m.cols());
  const double shift = pair_l(points_sensor_m, points_robot_m, 0, 1);
  const Moments m = reduce_sampled_pairs(
      points_sensor_m, points_robot_m, pairs, seed, Moments{},
      [shift](Moments& acc, double l) {
        const double d = l - shift;
        const double d2 = d * d;
        ++acc.n;
        acc.s1 += d;
        acc.s2 += d2;
        acc.s3 += d2 * d;
        acc.s4 += d2 * d2;
        acc.min = std::min(acc.min, l);
        acc.max = std::max(acc.max, l);
      },
      combine);
  const auto n = static_cast<double>(m.n);
  const double mean_d = m.s1 / n;
  // Central moments of the sample (divided by n) from the shifted power sums.
  const double c2 = std::max(0.0, m.s2 / n - mean_d * mean_d);
  const double c4 =
      std::max(0.0, m.s4 / n - 4.0 * mean_d * m.s3 / n + 6.0 * mean_d * mean_d * m.s2 / n -
                        3.0 * mean_d * mean_d * mean_d * mean_d);
  const double variance = c2 * n / (n - 1.0);  // unbiased, as the exact statistic
  const double se_variance = std::sqrt(std::max(0.0, c4 - c2 * c2) / n);

  RigidBodyEstimate out;
  out.statistics.pairs = m.n;
  out.statistics.mean_m = shift + mean_d;
  out.statistics.sigma_l_m = std::sqrt(variance);
  out.statistics.min_m = m.min;
  out.statistics.max_m = m.max;
  out.sampling.sampled = true;
  out.sampling.pairs_sampled = m.n;
  out.sampling.pairs_total = static_cast<std::int64_t>(j * (j - 1) / 2);
  out.sampling.seed = seed;
  out.sampling.confidence = 0.95;
  out.sampling.sigma_l_low_m = std::sqrt(std::max(0.0, variance - kZ95 * se_variance));
  out.sampling.sigma_l_high_m = std::sqrt(variance + kZ95 * se_variance);
  return out;
}

Histogram rigid_body_histogram_sampled(const ConstPoints3Ref& points_sensor_m,
                                       const ConstPoints3Ref& points_robot_m, int bins, double lo_m,
                                       double hi_m, std::int64_t pairs, std::uint64_t seed) {
  check_sample_input(points_sensor_m, points_robot_m, pairs);
  const Histogram empty = histogram(Eigen::VectorXd(), bins, lo_m, hi_m);  // checks bins, range
  return reduce_sampled_pairs(
      points_sensor_m, points_robot_m, pairs, seed, empty,
      [](Histogram& acc, double l) {  // the binning of rigid_body_histogram
        if (l < acc.lo_m) {
          ++acc.below;
          return;
        }
        const double bin = std::floor((l - acc.lo_m) / acc.bin_width_m);
        if (bin >= static_cast<double>(acc.counts.size())) {
          ++acc.above;
        } else {
          ++acc.counts[static_cast<std::size_t>(bin)];
        }
      },
      [](Histogram a, const Histogram& b) {
        for (std::size_t k = 0; k < a.counts.size(); ++k) a.counts[k] += b.counts[k];
        a.below += b.below;
        a.above += b.above;
        return a;
      });
}

RigidBodyEstimate rigid_body_estimate(const ConstPoints3Ref& points_sensor_m,
                                      const ConstPoints3Ref& points_robot_m,
                                      const SigmaLOptions& options) {
  options.validate();
  const auto j = static_cast<std::size_t>(points_sensor_m.cols());
  if (options.force_exact || j <= options.exact_max_points) {
    RigidBodyEstimate out;
    out.statistics = rigid_body_statistics(points_sensor_m, points_robot_m);
    out.sampling.pairs_total = out.statistics.pairs;
    out.sampling.pairs_sampled = out.statistics.pairs;
    return out;
  }
  return rigid_body_statistics_sampled(points_sensor_m, points_robot_m, options.sample_pairs,
                                       options.seed);
}

}  // namespace vrreg
