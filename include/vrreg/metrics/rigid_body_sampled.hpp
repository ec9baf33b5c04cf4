// SPDX-License-Identifier: Apache-2.0
#pragma once
// sigma_L (Eq. 1) for large fiducial sets: the exact statistic has J(J-1)/2 pairs (5e11 at a
// million fiducials), so above a size it is estimated from a seeded uniform sample of pairs, with
// a confidence interval, and says so (never a silent approximation).
#include <cstddef>
#include <cstdint>

#include "vrreg/core/types.hpp"
#include "vrreg/metrics/rigid_body.hpp"

namespace vrreg {

/// When and how sigma_L is sampled instead of computed over all pairs.
struct SigmaLOptions {
  /// Up to this many fiducials every pair is used (2e8 pairs, about 0.5 s on 2 cores).
  std::size_t exact_max_points = 20000;
  bool force_exact = false;                ///< every pair whatever the size (quadratic time)
  std::int64_t sample_pairs = 10'000'000;  ///< pairs drawn when sampling (95 % CI ~ +-0.05 %)
  std::uint64_t seed = 1;                  ///< seed of the pair sample: same seed, same bits
  /// Throws InputError unless sample_pairs >= 2.
  void validate() const;
};

/// How a sigma_L was obtained: exactly (sampled == false) or from a sample of pairs.
struct SigmaLSampling {
  bool sampled = false;
  std::int64_t pairs_sampled = 0;  ///< pairs drawn (uniformly, with replacement)
  std::int64_t pairs_total = 0;    ///< J(J-1)/2
  std::uint64_t seed = 0;
  double confidence = 0.95;    ///< of [sigma_l_low_m, sigma_l_high_m]
  double sigma_l_low_m = 0.0;  ///< confidence interval of the all-pairs sigma_L [m]
  double sigma_l_high_m = 0.0;
};

/// Statistics of L_ij and how they were obtained.
struct RigidBodyEstimate {
  RigidBodyStatistics statistics{};  ///< sampled: pairs = pairs drawn; min/max over the sample
  SigmaLSampling sampling{};
};

/// Mean and sigma_L of L_ij (Eq. 1) from `pairs` pairs (i != j) drawn uniformly with replacement
/// with `seed`, and a 95 % confidence interval of the all-pairs sigma_L: the draws are i.i.d. from
/// the finite population of all pairs, so Var(s^2) ~ (m4 - s^4) / pairs (delta method for s).
/// Deterministic: fixed chunks with their own streams, reduced in a fixed order.
RigidBodyEstimate rigid_body_statistics_sampled(const ConstPoints3Ref& points_sensor_m,
                                                const ConstPoints3Ref& points_robot_m,
                                                std::int64_t pairs, std::uint64_t seed);

/// Histogram of L_ij (as rigid_body_histogram) over the `pairs` pairs rigid_body_statistics_sampled
/// draws with the same `seed`: counts of sampled pairs, `bins` equal bins on [lo_m, hi_m).
Histogram rigid_body_histogram_sampled(const ConstPoints3Ref& points_sensor_m,
                                       const ConstPoints3Ref& points_robot_m, int bins, double lo_m,
                                       double hi_m, std::int64_t pairs, std::uint64_t seed);

/// rigid_body_statistics (all pairs) up to options.exact_max_points fiducials or when forced,
/// else rigid_body_statistics_sampled.
RigidBodyEstimate rigid_body_estimate(const ConstPoints3Ref& points_sensor_m,
                                      const ConstPoints3Ref& points_robot_m,
                                      const SigmaLOptions& options = {});

}  // namespace vrreg
