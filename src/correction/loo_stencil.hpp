// SPDX-License-Identifier: Apache-2.0
#pragma once
// Leave-one-out prediction of a fiducial's correction from its neighbours: the weights of a
// least-squares affine fit over the neighbours, evaluated at the fiducial (docs/outliers.md).
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg::detail {

/// Weights w_k with p_j = sum_k w_k eps_k; reproduces any affine field exactly.
struct LooStencil {
  std::vector<Eigen::Index> fiducial;
  std::vector<double> weight;
  double variance_factor = 0.0;  ///< 1 + sum w_k^2: Var(eps_j - p_j) / sigma^2 per axis
  bool ok = false;               ///< false: too few usable neighbours, or an unstable fit
};

/// Per fiducial, its up to k nearest others with the same group label (nearest first);
/// groups empty: one group.
std::vector<std::vector<Eigen::Index>> group_neighbours(const ConstPoints3Ref& points_m,
                                                        const std::vector<int>& groups, int k);

/// Weights over `neighbours` of a least-squares affine fit evaluated at `at_m` [m].
LooStencil affine_stencil(const ConstPoints3Ref& points_m, const Eigen::Vector3d& at_m,
                          std::vector<Eigen::Index> neighbours);

/// The LOO stencil of fiducial j from its neighbours that are `usable`.
LooStencil loo_stencil(const ConstPoints3Ref& points_m, Eigen::Index j,
                       const std::vector<Eigen::Index>& neighbours,
                       const std::vector<bool>& usable);

}  // namespace vrreg::detail
