// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid-body condition (Eq. 1): L_ij = ||X_i - X_j|| - ||Y_i - Y_j|| over all J(J-1)/2 pairs,
// exactly (no sampling), on both cores.
#include <cstdint>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// Statistics of L_ij over all pairs [m].
struct RigidBodyStatistics {
  std::int64_t pairs = 0;
  double mean_m = 0.0;
  double sigma_l_m = 0.0;  ///< sample standard deviation of L_ij (divides by pairs - 1)
  double min_m = 0.0;
  double max_m = 0.0;
};

/// Mean, sigma_L, min and max of L_ij (Eq. 1) over all pairs of corresponding points.
/// points_sensor_m, points_robot_m: the same fiducials in both frames [m]; needs >= 2 points.
/// The sum runs in a fixed order (deterministic reduce): the same input gives the same bits.
RigidBodyStatistics rigid_body_statistics(const ConstPoints3Ref& points_sensor_m,
                                          const ConstPoints3Ref& points_robot_m);

/// A histogram with equal bins on [lo_m, lo_m + bins * bin_width_m).
struct Histogram {
  double lo_m = 0.0;
  double bin_width_m = 0.0;
  std::vector<std::int64_t> counts{};
  std::int64_t below = 0;  ///< values under lo_m
  std::int64_t above = 0;  ///< values at or over the top edge
};

/// Histogram of L_ij (Eq. 1; paper Fig. 4-6) over all pairs, `bins` equal bins on [lo_m, hi_m).
Histogram rigid_body_histogram(const ConstPoints3Ref& points_sensor_m,
                               const ConstPoints3Ref& points_robot_m, int bins, double lo_m,
                               double hi_m);

/// Histogram of arbitrary values (e.g. Delta TRE, Fig. 11) with `bins` equal bins on [lo, hi).
Histogram histogram(const Eigen::Ref<const Eigen::VectorXd>& values, int bins, double lo,
                    double hi);

}  // namespace vrreg
