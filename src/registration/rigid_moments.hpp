// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal: the one-pass moments of register_rigid's fast path (RegistrationOptions::residuals =
// false). Four lanes over the points, products accumulated with a fused multiply-add, blocks of
// 128 points added (per lane) into compensated (hi + lo) totals, so the sums are accurate enough
// for the closed-form FRE. The AVX-512VL, AVX2 and portable kernels give the same bits (same
// lanes, same operations, std::fma is correctly rounded), so results do not depend on the CPU.
// Without FMA hardware std::fma is a library call: the portable kernel is then slow but exact.
#include <Eigen/Core>

#include "vrreg/core/types.hpp"

namespace vrreg::detail {

/// Indices into FastMoments::hi / lo.
enum MomentIndex : int {
  kSumX = 0,     ///< sum w a, 3 entries (a = x - shift_x)
  kSumY = 3,     ///< sum w b, 3 entries (b = y - shift_y)
  kSumXY = 6,    ///< sum w a b', row-major, 9 entries
  kSumXX = 15,   ///< sum w a a': 00 01 02 11 12 22
  kSumYY = 21,   ///< sum w |b|^2
  kWeight = 22,  ///< sum w (weighted only)
  kMoments = 23,
};

/// Sums about the shift points; the exact sum is about hi + lo.
struct FastMoments {
  double hi[kMoments] = {};
  double lo[kMoments] = {};
};

/// One pass over corresponding points x, y (3 x n) with optional weights (empty: all 1).
FastMoments fast_moments(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                         const Eigen::Ref<const Eigen::VectorXd>& w, const Eigen::Vector3d& shift_x,
                         const Eigen::Vector3d& shift_y);

/// The kernels fast_moments picks from (the widest the CPU has).
enum class MomentKernel { kPortable, kAvx2, kAvx512 };

/// The same sums by one named kernel, for tests that compare them bit for bit; false (and `out`
/// unchanged) when this CPU or build lacks it.
bool fast_moments_using(MomentKernel kernel, const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                        const Eigen::Ref<const Eigen::VectorXd>& w, const Eigen::Vector3d& shift_x,
                        const Eigen::Vector3d& shift_y, FastMoments& out);

}  // namespace vrreg::detail
