// SPDX-License-Identifier: Apache-2.0
#include "rigid_moments.hpp"

#include <cmath>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define VRREG_MOMENTS_AVX2 1
#endif

namespace vrreg::detail {
namespace {

constexpr int kLanes = 4;
constexpr int kGroupsPerBlock = 32;  // 128 points per block: short chains, then compensated totals

// Compensated totals per lane: the exact sum of the block sums is about hi + lo.
struct LaneTotals {
  alignas(32) double hi[kMoments][kLanes] = {};
  alignas(32) double lo[kMoments][kLanes] = {};
};

// TwoSum of a block's lane sums into the lane totals.
void add_block(LaneTotals& m, int k, const double lanes[kLanes]) {
  for (int l = 0; l < kLanes; ++l) {
    const double t = lanes[l];
    const double s = m.hi[k][l] + t;
    const double bt = s - m.hi[k][l];
    m.lo[k][l] += (m.hi[k][l] - (s - bt)) + (t - bt);
    m.hi[k][l] = s;
  }
}

// Lanes 1..3 added into lane 0 by TwoSum, their low parts with the errors.
FastMoments finish(const LaneTotals& t) {
  FastMoments m;
  for (int k = 0; k < kMoments; ++k) {
    double hi = t.hi[k][0], lo = t.lo[k][0];
    for (int l = 1; l < kLanes; ++l) {
      const double s = hi + t.hi[k][l];
      const double bt = s - hi;
      lo += ((hi - (s - bt)) + (t.hi[k][l] - bt)) + t.lo[k][l];
      hi = s;
    }
    m.hi[k] = hi;
    m.lo[k] = lo;
  }
  return m;
}

// Coordinates (minus the shift) and weights of the 4 points from column j; missing points (past
// n) get a = b = 0 and w = 0, which leave every sum unchanged.
struct Group {
  double a[3][kLanes];
  double b[3][kLanes];
  double w[kLanes];
};

void load_group(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                const Eigen::Ref<const Eigen::VectorXd>& w, const Eigen::Vector3d& shift_x,
                const Eigen::Vector3d& shift_y, Eigen::Index j, Group& g) {
  const Eigen::Index n = x.cols();
  for (int l = 0; l < kLanes; ++l) {
    const Eigen::Index c = j + l;
    for (int r = 0; r < 3; ++r) {
      g.a[r][l] = c < n ? x(r, c) - shift_x[r] : 0.0;
      g.b[r][l] = c < n ? y(r, c) - shift_y[r] : 0.0;
    }
    g.w[l] = c < n ? (w.size() != 0 ? w[c] : 1.0) : 0.0;
  }
}

// The portable kernel: the reference for the operations and their order.
template <bool kWeighted>
FastMoments portable(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                     const Eigen::Ref<const Eigen::VectorXd>& w, const Eigen::Vector3d& shift_x,
                     const Eigen::Vector3d& shift_y) {
  LaneTotals m;
  const Eigen::Index n = x.cols();
  for (Eigen::Index block = 0; block < n; block += kLanes * kGroupsPerBlock) {
    double acc[kMoments][kLanes] = {};
    const Eigen::Index end = std::min<Eigen::Index>(n, block + kLanes * kGroupsPerBlock);
    for (Eigen::Index j = block; j < end; j += kLanes) {
      Group g;
      load_group(x, y, w, shift_x, shift_y, j, g);
      for (int l = 0; l < kLanes; ++l) {
        double wa[3], wb[3];
        for (int r = 0; r < 3; ++r) {
          wa[r] = kWeighted ? g.w[l] * g.a[r][l] : g.a[r][l];
          wb[r] = kWeighted ? g.w[l] * g.b[r][l] : g.b[r][l];
        }
        if (kWeighted) acc[kWeight][l] += g.w[l];
        for (int r = 0; r < 3; ++r) {
          acc[kSumX + r][l] += wa[r];
          acc[kSumY + r][l] += wb[r];
          for (int c = 0; c < 3; ++c) {
            acc[kSumXY + 3 * r + c][l] = std::fma(wa[r], g.b[c][l], acc[kSumXY + 3 * r + c][l]);
          }
        }
        acc[kSumXX + 0][l] = std::fma(wa[0], g.a[0][l], acc[kSumXX + 0][l]);
        acc[kSumXX + 1][l] = std::fma(wa[0], g.a[1][l], acc[kSumXX + 1][l]);
        acc[kSumXX + 2][l] = std::fma(wa[0], g.a[2][l], acc[kSumXX + 2][l]);
        acc[kSumXX + 3][l] = std::fma(wa[1], g.a[1][l], acc[kSumXX + 3][l]);
        acc[kSumXX + 4][l] = std::fma(wa[1], g.a[2][l], acc[kSumXX + 4][l]);
        acc[kSumXX + 5][l] = std::fma(wa[2], g.a[2][l], acc[kSumXX + 5][l]);
        double t = wb[0] * g.b[0][l];
        t = std::fma(wb[1], g.b[1][l], t);
        t = std::fma(wb[2], g.b[2][l], t);
        acc[kSumYY][l] += t;
      }
    }
    for (int k = 0; k < kMoments; ++k) add_block(m, k, acc[k]);
  }
  return finish(m);
}

#ifdef VRREG_MOMENTS_AVX2

// x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3 -> (x0..x3), (y0..y3), (z0..z3).
[[gnu::target("avx2,fma")]] inline void deinterleave(const double* p, __m256d out[3]) {
  const __m256d r0 = _mm256_loadu_pd(p);
  const __m256d r1 = _mm256_loadu_pd(p + 4);
  const __m256d r2 = _mm256_loadu_pd(p + 8);
  const __m256d t0 = _mm256_blend_pd(r0, r1, 0b1100);       // x0 y0 x2 y2
  const __m256d t1 = _mm256_permute2f128_pd(r0, r2, 0x21);  // z0 x1 z2 x3
  const __m256d t2 = _mm256_blend_pd(r1, r2, 0b1100);       // y1 z1 y3 z3
  out[0] = _mm256_shuffle_pd(t0, t1, 0b1010);
  out[1] = _mm256_shuffle_pd(t0, t2, 0b0101);
  out[2] = _mm256_shuffle_pd(t1, t2, 0b1010);
}

// add_block on four lanes at once (the same operations per lane).
[[gnu::target("avx2,fma")]] inline void add_lanes(LaneTotals& m, int k, __m256d t) {
  const __m256d hi = _mm256_load_pd(m.hi[k]);
  const __m256d s = _mm256_add_pd(hi, t);
  const __m256d bt = _mm256_sub_pd(s, hi);
  const __m256d err = _mm256_add_pd(_mm256_sub_pd(hi, _mm256_sub_pd(s, bt)), _mm256_sub_pd(t, bt));
  _mm256_store_pd(m.lo[k], _mm256_add_pd(_mm256_load_pd(m.lo[k]), err));
  _mm256_store_pd(m.hi[k], s);
}

// The same operations as `portable`, four lanes per instruction. Three sweeps per block over the
// block's coordinates (kept in L1) keep every accumulator in a register.
template <bool kWeighted>
[[gnu::target("avx2,fma")]] FastMoments avx2(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                                             const Eigen::Ref<const Eigen::VectorXd>& w,
                                             const Eigen::Vector3d& shift_x,
                                             const Eigen::Vector3d& shift_y) {
  LaneTotals m;
  const Eigen::Index n = x.cols();
  const bool packed = x.outerStride() == 3 && y.outerStride() == 3;
  __m256d sx[3], sy[3];
  for (int r = 0; r < 3; ++r) {
    sx[r] = _mm256_set1_pd(shift_x[r]);
    sy[r] = _mm256_set1_pd(shift_y[r]);
  }
  alignas(32) __m256d buf[7][kGroupsPerBlock];  // a0 a1 a2 b0 b1 b2 w per group
  for (Eigen::Index block = 0; block < n; block += kLanes * kGroupsPerBlock) {
    const Eigen::Index end = std::min<Eigen::Index>(n, block + kLanes * kGroupsPerBlock);
    const int groups = static_cast<int>((end - block + kLanes - 1) / kLanes);
    // Sweep 1: coordinates minus shift into buf; first moments.
    __m256d s_w = _mm256_setzero_pd();
    __m256d s_a[3] = {_mm256_setzero_pd(), _mm256_setzero_pd(), _mm256_setzero_pd()};
    __m256d s_b[3] = {_mm256_setzero_pd(), _mm256_setzero_pd(), _mm256_setzero_pd()};
    for (int g = 0; g < groups; ++g) {
      const Eigen::Index j = block + kLanes * g;
      __m256d a[3], b[3], wv = _mm256_set1_pd(1.0);
      if (packed && j + kLanes <= n) {
        deinterleave(x.data() + 3 * j, a);
        deinterleave(y.data() + 3 * j, b);
        for (int r = 0; r < 3; ++r) {
          a[r] = _mm256_sub_pd(a[r], sx[r]);
          b[r] = _mm256_sub_pd(b[r], sy[r]);
        }
        if (kWeighted) wv = _mm256_loadu_pd(w.data() + j);
      } else {
        Group gr;
        load_group(x, y, w, shift_x, shift_y, j, gr);
        for (int r = 0; r < 3; ++r) {
          a[r] = _mm256_loadu_pd(gr.a[r]);
          b[r] = _mm256_loadu_pd(gr.b[r]);
        }
        wv = _mm256_loadu_pd(gr.w);
      }
      for (int r = 0; r < 3; ++r) {
        buf[r][g] = a[r];
        buf[3 + r][g] = b[r];
        s_a[r] = _mm256_add_pd(s_a[r], kWeighted ? _mm256_mul_pd(wv, a[r]) : a[r]);
        s_b[r] = _mm256_add_pd(s_b[r], kWeighted ? _mm256_mul_pd(wv, b[r]) : b[r]);
      }
      buf[6][g] = wv;
      if (kWeighted) s_w = _mm256_add_pd(s_w, wv);
    }
    // Sweep 2: cross moments.
    __m256d h[9];
    for (auto& v : h) v = _mm256_setzero_pd();
    for (int g = 0; g < groups; ++g) {
      for (int r = 0; r < 3; ++r) {
        const __m256d wa = kWeighted ? _mm256_mul_pd(buf[6][g], buf[r][g]) : buf[r][g];
        for (int c = 0; c < 3; ++c) h[3 * r + c] = _mm256_fmadd_pd(wa, buf[3 + c][g], h[3 * r + c]);
      }
    }
    // Sweep 3: second moments of each set.
    __m256d cxx[6], syy = _mm256_setzero_pd();
    for (auto& v : cxx) v = _mm256_setzero_pd();
    for (int g = 0; g < groups; ++g) {
      __m256d wa[3], wb[3];
      for (int r = 0; r < 3; ++r) {
        wa[r] = kWeighted ? _mm256_mul_pd(buf[6][g], buf[r][g]) : buf[r][g];
        wb[r] = kWeighted ? _mm256_mul_pd(buf[6][g], buf[3 + r][g]) : buf[3 + r][g];
      }
      cxx[0] = _mm256_fmadd_pd(wa[0], buf[0][g], cxx[0]);
      cxx[1] = _mm256_fmadd_pd(wa[0], buf[1][g], cxx[1]);
      cxx[2] = _mm256_fmadd_pd(wa[0], buf[2][g], cxx[2]);
      cxx[3] = _mm256_fmadd_pd(wa[1], buf[1][g], cxx[3]);
      cxx[4] = _mm256_fmadd_pd(wa[1], buf[2][g], cxx[4]);
      cxx[5] = _mm256_fmadd_pd(wa[2], buf[2][g], cxx[5]);
      __m256d t = _mm256_mul_pd(wb[0], buf[3][g]);
      t = _mm256_fmadd_pd(wb[1], buf[4][g], t);
      t = _mm256_fmadd_pd(wb[2], buf[5][g], t);
      syy = _mm256_add_pd(syy, t);
    }
    for (int r = 0; r < 3; ++r) {
      add_lanes(m, kSumX + r, s_a[r]);
      add_lanes(m, kSumY + r, s_b[r]);
    }
    for (int k = 0; k < 9; ++k) add_lanes(m, kSumXY + k, h[k]);
    for (int k = 0; k < 6; ++k) add_lanes(m, kSumXX + k, cxx[k]);
    add_lanes(m, kSumYY, syy);
    if (kWeighted) add_lanes(m, kWeight, s_w);
  }
  return finish(m);
}

// With AVX-512VL's 32 registers every accumulator stays in a register: one sweep, the same
// four-lane operations in the same order per accumulator (so the same bits as the others).
template <bool kWeighted>
[[gnu::target("avx2,fma,avx512f,avx512vl")]] FastMoments avx512vl(
    const ConstPoints3Ref& x, const ConstPoints3Ref& y, const Eigen::Ref<const Eigen::VectorXd>& w,
    const Eigen::Vector3d& shift_x, const Eigen::Vector3d& shift_y) {
  LaneTotals m;
  const Eigen::Index n = x.cols();
  const bool packed = x.outerStride() == 3 && y.outerStride() == 3;
  __m256d sx[3], sy[3];
  for (int r = 0; r < 3; ++r) {
    sx[r] = _mm256_set1_pd(shift_x[r]);
    sy[r] = _mm256_set1_pd(shift_y[r]);
  }
  for (Eigen::Index block = 0; block < n; block += kLanes * kGroupsPerBlock) {
    const Eigen::Index end = std::min<Eigen::Index>(n, block + kLanes * kGroupsPerBlock);
    __m256d s_w = _mm256_setzero_pd(), syy = _mm256_setzero_pd();
    __m256d s_a[3], s_b[3], h[9], cxx[6];
    for (auto& v : s_a) v = _mm256_setzero_pd();
    for (auto& v : s_b) v = _mm256_setzero_pd();
    for (auto& v : h) v = _mm256_setzero_pd();
    for (auto& v : cxx) v = _mm256_setzero_pd();
    for (Eigen::Index j = block; j < end; j += kLanes) {
      __m256d a[3], b[3], wv = _mm256_set1_pd(1.0);
      if (packed && j + kLanes <= n) {
        deinterleave(x.data() + 3 * j, a);
        deinterleave(y.data() + 3 * j, b);
        for (int r = 0; r < 3; ++r) {
          a[r] = _mm256_sub_pd(a[r], sx[r]);
          b[r] = _mm256_sub_pd(b[r], sy[r]);
        }
        if (kWeighted) wv = _mm256_loadu_pd(w.data() + j);
      } else {
        Group gr;
        load_group(x, y, w, shift_x, shift_y, j, gr);
        for (int r = 0; r < 3; ++r) {
          a[r] = _mm256_loadu_pd(gr.a[r]);
          b[r] = _mm256_loadu_pd(gr.b[r]);
        }
        wv = _mm256_loadu_pd(gr.w);
      }
      __m256d wa[3], wb[3];
      for (int r = 0; r < 3; ++r) {
        wa[r] = kWeighted ? _mm256_mul_pd(wv, a[r]) : a[r];
        wb[r] = kWeighted ? _mm256_mul_pd(wv, b[r]) : b[r];
        s_a[r] = _mm256_add_pd(s_a[r], wa[r]);
        s_b[r] = _mm256_add_pd(s_b[r], wb[r]);
      }
      if (kWeighted) s_w = _mm256_add_pd(s_w, wv);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) h[3 * r + c] = _mm256_fmadd_pd(wa[r], b[c], h[3 * r + c]);
      }
      cxx[0] = _mm256_fmadd_pd(wa[0], a[0], cxx[0]);
      cxx[1] = _mm256_fmadd_pd(wa[0], a[1], cxx[1]);
      cxx[2] = _mm256_fmadd_pd(wa[0], a[2], cxx[2]);
      cxx[3] = _mm256_fmadd_pd(wa[1], a[1], cxx[3]);
      cxx[4] = _mm256_fmadd_pd(wa[1], a[2], cxx[4]);
      cxx[5] = _mm256_fmadd_pd(wa[2], a[2], cxx[5]);
      __m256d t = _mm256_mul_pd(wb[0], b[0]);
      t = _mm256_fmadd_pd(wb[1], b[1], t);
      t = _mm256_fmadd_pd(wb[2], b[2], t);
      syy = _mm256_add_pd(syy, t);
    }
    for (int r = 0; r < 3; ++r) {
      add_lanes(m, kSumX + r, s_a[r]);
      add_lanes(m, kSumY + r, s_b[r]);
    }
    for (int k = 0; k < 9; ++k) add_lanes(m, kSumXY + k, h[k]);
    for (int k = 0; k < 6; ++k) add_lanes(m, kSumXX + k, cxx[k]);
    add_lanes(m, kSumYY, syy);
    if (kWeighted) add_lanes(m, kWeight, s_w);
  }
  return finish(m);
}

bool cpu_has_avx512vl() {
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                          __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  return has;
}

bool cpu_has_avx2_fma() {
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has;
}

#endif

}  // namespace

FastMoments fast_moments(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                         const Eigen::Ref<const Eigen::VectorXd>& w, const Eigen::Vector3d& shift_x,
                         const Eigen::Vector3d& shift_y) {
#ifdef VRREG_MOMENTS_AVX2
  if (cpu_has_avx512vl()) {
    return w.size() != 0 ? avx512vl<true>(x, y, w, shift_x, shift_y)
                         : avx512vl<false>(x, y, w, shift_x, shift_y);
  }
  if (cpu_has_avx2_fma()) {
    return w.size() != 0 ? avx2<true>(x, y, w, shift_x, shift_y)
                         : avx2<false>(x, y, w, shift_x, shift_y);
  }
#endif
  return w.size() != 0 ? portable<true>(x, y, w, shift_x, shift_y)
                       : portable<false>(x, y, w, shift_x, shift_y);
}

bool fast_moments_using(MomentKernel kernel, const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                        const Eigen::Ref<const Eigen::VectorXd>& w, const Eigen::Vector3d& shift_x,
                        const Eigen::Vector3d& shift_y, FastMoments& out) {
  const bool weighted = w.size() != 0;
  switch (kernel) {
    case MomentKernel::kPortable:
      out = weighted ? portable<true>(x, y, w, shift_x, shift_y)
                     : portable<false>(x, y, w, shift_x, shift_y);
      return true;
#ifdef VRREG_MOMENTS_AVX2
    case MomentKernel::kAvx2:
      if (!cpu_has_avx2_fma()) return false;
      out =
          weighted ? avx2<true>(x, y, w, shift_x, shift_y) : avx2<false>(x, y, w, shift_x, shift_y);
      return true;
    case MomentKernel::kAvx512:
      if (!cpu_has_avx512vl()) return false;
      out = weighted ? avx512vl<true>(x, y, w, shift_x, shift_y)
                     : avx512vl<false>(x, y, w, shift_x, shift_y);
      return true;
#endif
    default:
      return false;
  }
}

}  // namespace vrreg::detail
