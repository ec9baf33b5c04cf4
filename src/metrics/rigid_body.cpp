// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/rigid_body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#endif

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

constexpr std::size_t kLanes = 4;  // leaves folded side by side, one per AVX2 lane

// Four leaves at once, leaf k in lane k: each lane's sums still run over its own pairs in
// for_pairs' order (row by row, j ascending), so every leaf gets the bits it gets alone; the
// lanes only share the instructions. Row step r takes row first_k + r of every leaf; the lanes
// walk j together from the largest start, the few j before it (each lane's row starts at its own
// i + 1) are added first, one lane at a time. A leaf with fewer rows idles in its last steps:
// its lane computes a row whose sums are then dropped.
[[gnu::target("avx2")]] void fold_leaves4_avx2(const PairData& d,
                                               const std::pair<std::size_t, std::size_t>* leaf,
                                               Sums* out) {
  const std::size_t n = d.x[0].size();
  const double* const x0 = d.x[0].data();
  const double* const x1 = d.x[1].data();
  const double* const x2 = d.x[2].data();
  const double* const y0 = d.y[0].data();
  const double* const y1 = d.y[1].data();
  const double* const y2 = d.y[2].data();
  alignas(32) double sum[kLanes], sum_sq[kLanes], lo[kLanes], hi[kLanes];
  std::size_t steps = 0;
  for (std::size_t k = 0; k < kLanes; ++k) {
    sum[k] = out[k].sum;
    sum_sq[k] = out[k].sum_sq;
    lo[k] = out[k].min;
    hi[k] = out[k].max;
    steps = std::max(steps, leaf[k].second - leaf[k].first);
  }
  for (std::size_t r = 0; r < steps; ++r) {
    std::size_t row[kLanes];
    bool active[kLanes];
    std::size_t start = 0;  // where the lanes walk together
    for (std::size_t k = 0; k < kLanes; ++k) {
      active[k] = leaf[k].first + r < leaf[k].second;
      row[k] = active[k] ? leaf[k].first + r : leaf[k].first;
      if (active[k]) start = std::max(start, row[k] + 1);
    }
    start = std::min(start, n);
    for (std::size_t k = 0; k < kLanes; ++k) {
      if (!active[k]) continue;
      const std::size_t i = row[k];
      for (std::size_t j = i + 1; j < start; ++j) {
        const double a0 = x0[j] - x0[i], a1 = x1[j] - x1[i], a2 = x2[j] - x2[i];
        const double b0 = y0[j] - y0[i], b1 = y1[j] - y1[i], b2 = y2[j] - y2[i];
        const double l =
            std::sqrt(a0 * a0 + a1 * a1 + a2 * a2) - std::sqrt(b0 * b0 + b1 * b1 + b2 * b2);
        sum[k] += l;
        sum_sq[k] += l * l;
        lo[k] = std::min(lo[k], l);
        hi[k] = std::max(hi[k], l);
      }
      out[k].n += static_cast<std::int64_t>(n - i - 1);
    }
    if (start >= n) continue;
    const __m256d xi0 = _mm256_set_pd(x0[row[3]], x0[row[2]], x0[row[1]], x0[row[0]]);
    const __m256d xi1 = _mm256_set_pd(x1[row[3]], x1[row[2]], x1[row[1]], x1[row[0]]);
    const __m256d xi2 = _mm256_set_pd(x2[row[3]], x2[row[2]], x2[row[1]], x2[row[0]]);
    const __m256d yi0 = _mm256_set_pd(y0[row[3]], y0[row[2]], y0[row[1]], y0[row[0]]);
    const __m256d yi1 = _mm256_set_pd(y1[row[3]], y1[row[2]], y1[row[1]], y1[row[0]]);
    const __m256d yi2 = _mm256_set_pd(y2[row[3]], y2[row[2]], y2[row[1]], y2[row[0]]);
    __m256d vsum = _mm256_load_pd(sum), vsq = _mm256_load_pd(sum_sq);
    __m256d vlo = _mm256_load_pd(lo), vhi = _mm256_load_pd(hi);
    for (std::size_t j = start; j < n; ++j) {
      const __m256d a0 = _mm256_sub_pd(_mm256_broadcast_sd(x0 + j), xi0);
      const __m256d a1 = _mm256_sub_pd(_mm256_broadcast_sd(x1 + j), xi1);
      const __m256d a2 = _mm256_sub_pd(_mm256_broadcast_sd(x2 + j), xi2);
      const __m256d b0 = _mm256_sub_pd(_mm256_broadcast_sd(y0 + j), yi0);
      const __m256d b1 = _mm256_sub_pd(_mm256_broadcast_sd(y1 + j), yi1);
      const __m256d b2 = _mm256_sub_pd(_mm256_broadcast_sd(y2 + j), yi2);
      const __m256d aa = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a0, a0), _mm256_mul_pd(a1, a1)),
                                       _mm256_mul_pd(a2, a2));
      const __m256d bb = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(b0, b0), _mm256_mul_pd(b1, b1)),
                                       _mm256_mul_pd(b2, b2));
      const __m256d l = _mm256_sub_pd(_mm256_sqrt_pd(aa), _mm256_sqrt_pd(bb));
      vsum = _mm256_add_pd(vsum, l);
      vsq = _mm256_add_pd(vsq, _mm256_mul_pd(l, l));
      vlo = _mm256_min_pd(vlo, l);
      vhi = _mm256_max_pd(vhi, l);
    }
    alignas(32) double t_sum[kLanes], t_sq[kLanes], t_lo[kLanes], t_hi[kLanes];
    _mm256_store_pd(t_sum, vsum);
    _mm256_store_pd(t_sq, vsq);
    _mm256_store_pd(t_lo, vlo);
    _mm256_store_pd(t_hi, vhi);
    for (std::size_t k = 0; k < kLanes; ++k) {
      if (!active[k]) continue;  // an idle lane's row is dropped
      sum[k] = t_sum[k];
      sum_sq[k] = t_sq[k];
      lo[k] = t_lo[k];
      hi[k] = t_hi[k];
    }
  }
  for (std::size_t k = 0; k < kLanes; ++k) {
    out[k].sum = sum[k];
    out[k].sum_sq = sum_sq[k];
    out[k].min = lo[k];
    out[k].max = hi[k];
  }
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

// Leaves [first, last) of rows into leaf (each from zero sums): four at a time where AVX2 is.
void fold_leaves(const PairData& d, const std::vector<std::pair<std::size_t, std::size_t>>& rows,
                 std::size_t first, std::size_t last, std::vector<Sums>& leaf) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  if (cpu_has_avx2()) {
    for (; first + kLanes <= last; first += kLanes) {
      fold_leaves4_avx2(d, rows.data() + first, leaf.data() + first);
    }
  }
#endif
  for (; first < last; ++first) fold(d, rows[first].first, rows[first].second, leaf[first]);
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
  // Groups of kGroup neighbouring leaves (similar lengths) per task.
  constexpr std::size_t kGroup = 4;
  const std::size_t groups = (rows.size() + kGroup - 1) / kGroup;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups, 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      fold_leaves(data, rows, r.begin() * kGroup,
                                  std::min(rows.size(), r.end() * kGroup), leaf);
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
