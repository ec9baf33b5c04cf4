#include "vrreg/metrics/rigid_body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

struct Sums {
  std::int64_t n = 0;
  double sum = 0.0;
  double sum_sq = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
};

void check_pair_input(const ConstPoints3Ref& x, const ConstPoints3Ref& y) {
  VRREG_THROW_UNLESS(x.cols() == y.cols(), "rigid-body condition needs corresponding points: "
                                               << x.cols() << " vs " << y.cols());
  VRREG_THROW_UNLESS(x.cols() >= 2, "rigid-body condition needs at least 2 points");
  VRREG_THROW_UNLESS(x.allFinite() && y.allFinite(), "rigid-body condition: non-finite point");
}

// Calls f(L_ij) for every pair with i in [row_begin, row_end) and j > i.
template <typename F>
void for_pairs(const ConstPoints3Ref& x, const ConstPoints3Ref& y, Eigen::Index row_begin,
               Eigen::Index row_end, F&& f) {
  const Eigen::Index n = x.cols();
  for (Eigen::Index i = row_begin; i < row_end; ++i) {
    const double xi0 = x(0, i), xi1 = x(1, i), xi2 = x(2, i);
    const double yi0 = y(0, i), yi1 = y(1, i), yi2 = y(2, i);
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const double a0 = x(0, j) - xi0, a1 = x(1, j) - xi1, a2 = x(2, j) - xi2;
      const double b0 = y(0, j) - yi0, b1 = y(1, j) - yi1, b2 = y(2, j) - yi2;
      f(std::sqrt(a0 * a0 + a1 * a1 + a2 * a2) - std::sqrt(b0 * b0 + b1 * b1 + b2 * b2));
    }
  }
}

// Rows are split into ranges of equal pair counts would be ideal; rows near the top are longer,
// so a fine grain keeps both cores busy. Deterministic reduce: fixed split, fixed order.
constexpr std::size_t kRowGrain = 16;

}  // namespace

RigidBodyStatistics rigid_body_statistics(const ConstPoints3Ref& points_sensor_m,
                                          const ConstPoints3Ref& points_robot_m) {
  check_pair_input(points_sensor_m, points_robot_m);
  const auto n = static_cast<std::size_t>(points_sensor_m.cols());
  const Sums total = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::size_t>(0, n, kRowGrain), Sums{},
      [&](const tbb::blocked_range<std::size_t>& rows, Sums acc) {
        for_pairs(points_sensor_m, points_robot_m, static_cast<Eigen::Index>(rows.begin()),
                  static_cast<Eigen::Index>(rows.end()), [&acc](double l) {
                    ++acc.n;
                    acc.sum += l;
                    acc.sum_sq += l * l;
                    acc.min = std::min(acc.min, l);
                    acc.max = std::max(acc.max, l);
                  });
        return acc;
      },
      [](Sums a, const Sums& b) {
        a.n += b.n;
        a.sum += b.sum;
        a.sum_sq += b.sum_sq;
        a.min = std::min(a.min, b.min);
        a.max = std::max(a.max, b.max);
        return a;
      });
  RigidBodyStatistics s;
  s.pairs = total.n;
  const auto count = static_cast<double>(total.n);
  s.mean_m = total.sum / count;
  // L_ij is small and centred near zero, so the one-pass variance loses nothing that matters.
  const double ss = std::max(0.0, total.sum_sq - total.sum * s.mean_m);
  s.sigma_l_m = total.n > 1 ? std::sqrt(ss / (count - 1.0)) : 0.0;
  s.min_m = total.min;
  s.max_m = total.max;
  return s;
}

namespace {
void add_to(Histogram& h, double value) {
  if (value < h.lo_m) {
    ++h.below;
    return;
  }
  const double bin = std::floor((value - h.lo_m) / h.bin_width_m);
  if (bin >= static_cast<double>(h.counts.size())) {
    ++h.above;
    return;
  }
  ++h.counts[static_cast<std::size_t>(bin)];
}

Histogram empty_histogram(int bins, double lo, double hi) {
  VRREG_THROW_UNLESS(bins > 0, "histogram needs a positive number of bins, got " << bins);
  VRREG_THROW_UNLESS(std::isfinite(lo) && std::isfinite(hi) && hi > lo,
                     "histogram range must be finite with hi > lo, got [" << lo << ", " << hi
                                                                          << ")");
  Histogram h;
  h.lo_m = lo;
  h.bin_width_m = (hi - lo) / bins;
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  return h;
}
}  // namespace

Histogram rigid_body_histogram(const ConstPoints3Ref& points_sensor_m,
                               const ConstPoints3Ref& points_robot_m, int bins, double lo_m,
                               double hi_m) {
  check_pair_input(points_sensor_m, points_robot_m);
  const Histogram empty = empty_histogram(bins, lo_m, hi_m);
  const auto n = static_cast<std::size_t>(points_sensor_m.cols());
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::size_t>(0, n, kRowGrain), empty,
      [&](const tbb::blocked_range<std::size_t>& rows, Histogram acc) {
        for_pairs(points_sensor_m, points_robot_m, static_cast<Eigen::Index>(rows.begin()),
                  static_cast<Eigen::Index>(rows.end()), [&acc](double l) { add_to(acc, l); });
        return acc;
      },
      [](Histogram a, const Histogram& b) {
        for (std::size_t k = 0; k < a.counts.size(); ++k) a.counts[k] += b.counts[k];
        a.below += b.below;
        a.above += b.above;
        return a;
      });
}

Histogram histogram(const Eigen::Ref<const Eigen::VectorXd>& values, int bins, double lo,
                    double hi) {
  Histogram h = empty_histogram(bins, lo, hi);
  for (Eigen::Index k = 0; k < values.size(); ++k) add_to(h, values[k]);
  return h;
}

}  // namespace vrreg
