#include "vrreg/metrics/rigid_body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
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

namespace {

// The points as six coordinate arrays (structure of arrays) for the vectorised row kernel.
struct PairData {
  std::vector<double> x[3], y[3];
  explicit PairData(const ConstPoints3Ref& xs, const ConstPoints3Ref& ys) {
    const auto n = static_cast<std::size_t>(xs.cols());
    for (int a = 0; a < 3; ++a) {
      x[a].resize(n);
      y[a].resize(n);
      for (std::size_t j = 0; j < n; ++j) {
        x[a][j] = xs(a, static_cast<Eigen::Index>(j));
        y[a][j] = ys(a, static_cast<Eigen::Index>(j));
      }
    }
  }
};

constexpr std::size_t kChunk = 256;  // pairs per vectorised chunk (fits in L1 with the inputs)

// L_ij for j in [j0, j0 + m) into out: the same operations in the same order as for_pairs, so the
// same bits at any vector width (-ffp-contract=off on this file keeps them unfused).
template <int kTarget>
[[gnu::always_inline]] inline void pair_lengths(const PairData& d, std::size_t i, std::size_t j0,
                                                std::size_t m, double* out) {
  const double xi0 = d.x[0][i], xi1 = d.x[1][i], xi2 = d.x[2][i];
  const double yi0 = d.y[0][i], yi1 = d.y[1][i], yi2 = d.y[2][i];
  const double* __restrict x0 = d.x[0].data() + j0;
  const double* __restrict x1 = d.x[1].data() + j0;
  const double* __restrict x2 = d.x[2].data() + j0;
  const double* __restrict y0 = d.y[0].data() + j0;
  const double* __restrict y1 = d.y[1].data() + j0;
  const double* __restrict y2 = d.y[2].data() + j0;
  for (std::size_t k = 0; k < m; ++k) {
    const double a0 = x0[k] - xi0, a1 = x1[k] - xi1, a2 = x2[k] - xi2;
    const double b0 = y0[k] - yi0, b1 = y1[k] - yi1, b2 = y2[k] - yi2;
    out[k] = std::sqrt(a0 * a0 + a1 * a1 + a2 * a2) - std::sqrt(b0 * b0 + b1 * b1 + b2 * b2);
  }
}

// The pairs of rows [row_begin, row_end) folded into acc in for_pairs' order: the sums run in
// sequence (the bits of the reference order).
template <int kTarget>
[[gnu::always_inline]] inline void fold_rows(const PairData& d, std::size_t row_begin,
                                             std::size_t row_end, Sums& acc) {
  const std::size_t n = d.x[0].size();
  alignas(64) double l[kChunk];
  for (std::size_t i = row_begin; i < row_end; ++i) {
    for (std::size_t j0 = i + 1; j0 < n; j0 += kChunk) {
      const std::size_t m = std::min(kChunk, n - j0);
      pair_lengths<kTarget>(d, i, j0, m, l);
      double sum = acc.sum, sum_sq = acc.sum_sq, lo = acc.min, hi = acc.max;
      for (std::size_t k = 0; k < m; ++k) {  // min and max ride along the sums' latency
        sum += l[k];
        sum_sq += l[k] * l[k];
        lo = std::min(lo, l[k]);
        hi = std::max(hi, l[k]);
      }
      acc.sum = sum;
      acc.sum_sq = sum_sq;
      acc.min = lo;
      acc.max = hi;
      acc.n += static_cast<std::int64_t>(m);
    }
  }
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
[[gnu::target("avx2")]] void fold_rows_avx2(const PairData& d, std::size_t b, std::size_t e,
                                            Sums& acc) {
  fold_rows<1>(d, b, e, acc);
}
bool cpu_has_avx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
#endif

void fold(const PairData& d, std::size_t b, std::size_t e, Sums& acc) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  if (cpu_has_avx2()) return fold_rows_avx2(d, b, e, acc);
#endif
  fold_rows<0>(d, b, e, acc);
}

Sums combine(Sums a, const Sums& b) {
  a.n += b.n;
  a.sum += b.sum;
  a.sum_sq += b.sum_sq;
  a.min = std::min(a.min, b.min);
  a.max = std::max(a.max, b.max);
  return a;
}

// The fixed partition: blocked_range(0, n, kRowGrain) halved (begin + size / 2) until at most
// kRowGrain rows, the leaves in order. This is the tree tbb::parallel_deterministic_reduce
// builds, so the sums come out as they always have, on any number of threads.
void leaves(std::size_t b, std::size_t e, std::vector<std::pair<std::size_t, std::size_t>>& out) {
  if (e - b > kRowGrain) {
    const std::size_t mid = b + (e - b) / 2;
    leaves(b, mid, out);
    leaves(mid, e, out);
  } else {
    out.emplace_back(b, e);
  }
}

// Joins the leaf sums in the same tree: left with right at every split.
Sums join_tree(std::size_t b, std::size_t e, const std::vector<Sums>& leaf, std::size_t& next) {
  if (e - b > kRowGrain) {
    const std::size_t mid = b + (e - b) / 2;
    const Sums left = join_tree(b, mid, leaf, next);
    return combine(left, join_tree(mid, e, leaf, next));
  }
  return leaf[next++];
}

}  // namespace

RigidBodyStatistics rigid_body_statistics(const ConstPoints3Ref& points_sensor_m,
                                          const ConstPoints3Ref& points_robot_m) {
  check_pair_input(points_sensor_m, points_robot_m);
  const auto n = static_cast<std::size_t>(points_sensor_m.cols());
  const PairData data(points_sensor_m, points_robot_m);
  std::vector<std::pair<std::size_t, std::size_t>> rows;
  leaves(0, n, rows);
  // Leaves are independent; each one's sums start from zero, so the thread count cannot change
  // a bit. Fine tasks (one leaf each) balance the long early rows against the short late ones.
  std::vector<Sums> leaf(rows.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k) {
                        fold(data, rows[k].first, rows[k].second, leaf[k]);
                      }
                    });
  std::size_t next = 0;
  const Sums total = join_tree(0, n, leaf, next);
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
