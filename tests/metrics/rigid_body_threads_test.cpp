// SPDX-License-Identifier: Apache-2.0
// sigma_L (Eq. 1) over all pairs: the vectorised, threaded kernel gives the bits of the plain
// loop folded in tbb::parallel_deterministic_reduce's fixed tree (the implementation before it,
// kept here as the reference), on any number of threads.
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <limits>

#include "vrreg/metrics/rigid_body.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

struct Sums {
  std::int64_t n = 0;
  double sum = 0.0, sum_sq = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
};

// The naive pair loop (scalar, one pair at a time) in the deterministic reduce with 16-row grain.
RigidBodyStatistics naive_reference(const Points3& x, const Points3& y) {
  const auto n = static_cast<std::size_t>(x.cols());
  const Sums t = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::size_t>(0, n, 16), Sums{},
      [&](const tbb::blocked_range<std::size_t>& rows, Sums acc) {
        for (auto i = static_cast<Eigen::Index>(rows.begin());
             i < static_cast<Eigen::Index>(rows.end()); ++i) {
          for (Eigen::Index j = i + 1; j < x.cols(); ++j) {
            const double a0 = x(0, j) - x(0, i), a1 = x(1, j) - x(1, i), a2 = x(2, j) - x(2, i);
            const double b0 = y(0, j) - y(0, i), b1 = y(1, j) - y(1, i), b2 = y(2, j) - y(2, i);
            const double l =
                std::sqrt(a0 * a0 + a1 * a1 + a2 * a2) - std::sqrt(b0 * b0 + b1 * b1 + b2 * b2);
            ++acc.n;
            acc.sum += l;
            acc.sum_sq += l * l;
            acc.min = std::min(acc.min, l);
            acc.max = std::max(acc.max, l);
          }
        }
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
  s.pairs = t.n;
  const auto count = static_cast<double>(t.n);
  s.mean_m = t.sum / count;
  const double ss = std::max(0.0, t.sum_sq - t.sum * s.mean_m);
  s.sigma_l_m = t.n > 1 ? std::sqrt(ss / (count - 1.0)) : 0.0;
  s.min_m = t.min;
  s.max_m = t.max;
  return s;
}

void expect_same_bits(const RigidBodyStatistics& a, const RigidBodyStatistics& b) {
  EXPECT_EQ(a.pairs, b.pairs);
  EXPECT_EQ(a.mean_m, b.mean_m);
  EXPECT_EQ(a.sigma_l_m, b.sigma_l_m);
  EXPECT_EQ(a.min_m, b.min_m);
  EXPECT_EQ(a.max_m, b.max_m);
}

TEST(RigidBodyThreads, SameBitsAsNaiveLoopOnAnyThreadCount) {
  Random rng(43);
  for (const int n : {2, 3, 16, 17, 33, 255, 256, 257, 519, 1500}) {
    SCOPED_TRACE(n);
    const Points3 x = testing::random_points(rng, n, 0.15, Eigen::Vector3d(0.4, 1.0, 2.0));
    Points3 y = testing::random_transform(rng, 1.0).apply_all(x);
    for (int j = 0; j < n; ++j) y.col(j) += rng.normal3(0.3e-3);
    const RigidBodyStatistics reference = naive_reference(x, y);
    for (const int threads : {1, 2, 3}) {
      const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(threads));
      expect_same_bits(rigid_body_statistics(x, y), reference);
    }
  }
}

// A strided view (part of a larger matrix) gives the same bits as a packed copy.
TEST(RigidBodyThreads, StridedInput) {
  Random rng(44);
  Eigen::MatrixXd big = Eigen::MatrixXd::Random(6, 300);
  const Eigen::Map<const Eigen::Matrix3Xd, 0, Eigen::OuterStride<>> x(big.data(), 3, 300,
                                                                      Eigen::OuterStride<>(6));
  const Eigen::Map<const Eigen::Matrix3Xd, 0, Eigen::OuterStride<>> y(big.data() + 3, 3, 300,
                                                                      Eigen::OuterStride<>(6));
  expect_same_bits(rigid_body_statistics(x, y), naive_reference(Points3(x), Points3(y)));
}

}  // namespace
}  // namespace vrreg
