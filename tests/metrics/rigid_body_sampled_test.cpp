// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/rigid_body_sampled.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <mutex>
#include <string>

#include "vrreg/core/check.hpp"
#include "vrreg/core/progress.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

// Fiducials in a 0.3 m volume; the "robot" copy has a smooth distortion and noise, so that L_ij
// has a spread like a real cell's (sigma_L ~ 0.1 mm) and a non-Gaussian shape.
struct Cell {
  Points3 sensor, robot;
};
Cell cell(int n, std::uint64_t seed) {
  Random rng(seed);
  Cell c;
  c.sensor = testing::random_points(rng, n, 0.15, Eigen::Vector3d(0.4, 1.0, 2.0));
  c.robot = c.sensor;
  for (Eigen::Index j = 0; j < c.robot.cols(); ++j) {
    const Eigen::Vector3d p = c.sensor.col(j);
    c.robot.col(j) +=
        Eigen::Vector3d(2e-4 * std::sin(20.0 * p.y()), 1e-4 * p.x(), 0.0) + rng.normal3(3e-5);
  }
  return c;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(RigidBodySampled, IntervalCoversTheExactSigmaL) {
  const Cell c = cell(2000, 3);  // 1 999 000 pairs: exact is cheap here
  const RigidBodyStatistics exact = rigid_body_statistics(c.sensor, c.robot);
  int covered = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const RigidBodyEstimate s = rigid_body_statistics_sampled(c.sensor, c.robot, 200000, seed);
    ASSERT_TRUE(s.sampling.sampled);
    EXPECT_EQ(s.sampling.pairs_sampled, 200000);
    EXPECT_EQ(s.sampling.pairs_total, 1999000);
    EXPECT_LT(s.sampling.sigma_l_low_m, s.statistics.sigma_l_m);
    EXPECT_GT(s.sampling.sigma_l_high_m, s.statistics.sigma_l_m);
    // The interval is a few tenths of a percent wide at 2e5 pairs, not a blanket.
    EXPECT_LT(s.sampling.sigma_l_high_m - s.sampling.sigma_l_low_m, 0.02 * exact.sigma_l_m);
    EXPECT_NEAR(s.statistics.mean_m, exact.mean_m, 0.02 * exact.sigma_l_m);
    if (s.sampling.sigma_l_low_m <= exact.sigma_l_m && exact.sigma_l_m <= s.sampling.sigma_l_high_m)
      ++covered;
  }
  // 95 % intervals: 17 or more of 20 (binomial probability of fewer: 1.6 %; seeds are fixed).
  EXPECT_GE(covered, 17);
}

TEST(RigidBodySampled, SameSeedSameBitsOnAnyNumberOfThreads) {
  const Cell c = cell(5000, 4);
  const RigidBodyEstimate a = rigid_body_statistics_sampled(c.sensor, c.robot, 300001, 9);
  RigidBodyEstimate b;
  tbb::task_arena one_thread(1);
  one_thread.execute([&] { b = rigid_body_statistics_sampled(c.sensor, c.robot, 300001, 9); });
  EXPECT_TRUE(same_bits(a.statistics.sigma_l_m, b.statistics.sigma_l_m));
  EXPECT_TRUE(same_bits(a.statistics.mean_m, b.statistics.mean_m));
  EXPECT_TRUE(same_bits(a.sampling.sigma_l_low_m, b.sampling.sigma_l_low_m));
  EXPECT_TRUE(same_bits(a.sampling.sigma_l_high_m, b.sampling.sigma_l_high_m));
  EXPECT_EQ(a.statistics.pairs, 300001);
  const RigidBodyEstimate other = rigid_body_statistics_sampled(c.sensor, c.robot, 300001, 10);
  EXPECT_FALSE(same_bits(a.statistics.sigma_l_m, other.statistics.sigma_l_m));
}

TEST(RigidBodySampled, EstimateIsExactUpToTheThresholdOrWhenForced) {
  const Cell c = cell(300, 5);
  const RigidBodyStatistics exact = rigid_body_statistics(c.sensor, c.robot);
  SigmaLOptions options;
  RigidBodyEstimate e = rigid_body_estimate(c.sensor, c.robot, options);
  EXPECT_FALSE(e.sampling.sampled);
  EXPECT_TRUE(same_bits(e.statistics.sigma_l_m, exact.sigma_l_m));
  EXPECT_EQ(e.sampling.pairs_total, 300 * 299 / 2);

  options.exact_max_points = 299;
  options.sample_pairs = 1000;
  e = rigid_body_estimate(c.sensor, c.robot, options);
  EXPECT_TRUE(e.sampling.sampled);
  EXPECT_EQ(e.statistics.pairs, 1000);

  options.force_exact = true;
  e = rigid_body_estimate(c.sensor, c.robot, options);
  EXPECT_FALSE(e.sampling.sampled);
  EXPECT_TRUE(same_bits(e.statistics.sigma_l_m, exact.sigma_l_m));
}

TEST(RigidBodySampled, HistogramOfTheSampleHasTheShapeOfTheExactOne) {
  const Cell c = cell(1500, 7);
  const RigidBodyStatistics exact = rigid_body_statistics(c.sensor, c.robot);
  const double lo = exact.mean_m - 4 * exact.sigma_l_m, hi = exact.mean_m + 4 * exact.sigma_l_m;
  const Histogram all = rigid_body_histogram(c.sensor, c.robot, 20, lo, hi);
  const Histogram sample = rigid_body_histogram_sampled(c.sensor, c.robot, 20, lo, hi, 400000, 3);
  std::int64_t total = sample.below + sample.above;
  for (std::size_t k = 0; k < sample.counts.size(); ++k) {
    total += sample.counts[k];
    // Bin shares agree to sampling noise (at most ~0.0008 standard error at 4e5 pairs).
    EXPECT_NEAR(static_cast<double>(sample.counts[k]) / 400000.0,
                static_cast<double>(all.counts[k]) / static_cast<double>(exact.pairs), 0.004)
        << "bin " << k;
  }
  EXPECT_EQ(total, 400000);
  EXPECT_EQ(rigid_body_histogram_sampled(c.sensor, c.robot, 20, lo, hi, 400000, 3).counts,
            sample.counts);
}

TEST(RigidBodySampled, BadInputThrows) {
  const Cell c = cell(10, 6);
  EXPECT_THROW(rigid_body_statistics_sampled(c.sensor, c.robot, 1, 1), InputError);
  EXPECT_THROW(rigid_body_statistics_sampled(c.sensor.leftCols(1), c.robot.leftCols(1), 10, 1),
               InputError);
  EXPECT_THROW(rigid_body_statistics_sampled(c.sensor, c.robot.leftCols(9), 10, 1), InputError);
  Points3 bad = c.sensor;
  bad(0, 3) = std::nan("");
  EXPECT_THROW(rigid_body_statistics_sampled(bad, c.robot, 10, 1), InputError);
  SigmaLOptions options;
  options.sample_pairs = 0;
  EXPECT_THROW(rigid_body_estimate(c.sensor, c.robot, options), InputError);
}

// Sampling 10^7 pairs takes a second: it reports progress, one step per chunk, to its end.
TEST(RigidBodySampled, ReportsProgressToItsEnd) {
  const Cell c = cell(300, 4);
  std::mutex mutex;
  std::int64_t last_done = -1;
  std::int64_t last_total = -2;
  std::string name;
  set_progress_sink([&](std::string_view stage, std::int64_t done, std::int64_t total, double) {
    const std::lock_guard<std::mutex> lock(mutex);
    name = stage;
    last_done = std::max(last_done, done);
    last_total = total;
  });
  (void)rigid_body_statistics_sampled(c.sensor, c.robot, 300001, 9);
  set_progress_sink({});
  EXPECT_EQ(name, "sigma_L over 300001 sampled pairs");
  EXPECT_GT(last_total, 1);
  EXPECT_EQ(last_done, last_total);
}

}  // namespace
}  // namespace vrreg
