// SPDX-License-Identifier: Apache-2.0
#pragma once
// Hyperparameters of one axis of a universal-kriging model by maximum restricted likelihood
// (REML) from deterministic starts (docs/field-models.md, "Hyperparameters").
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "field_basis.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/correction/kriging.hpp"

namespace vrreg::detail {

/// `size` fiducials (all if size >= J) in clusters: each the `cluster` nearest fiducials of a
/// centre drawn by a seeded shuffle, until `size` are taken. A uniform subset of a dense grid
/// loses the short pairs that reveal a short length scale (a vertical column of one azimuth);
/// clusters keep them, and the spread of the centres keeps the long ones. The centres come
/// from a splitmix64 Fisher-Yates shuffle: same seed, same subset on every platform; cluster 1
/// is a uniform draw.
[[nodiscard]] std::vector<Eigen::Index> seeded_cluster_subset(const ConstPoints3Ref& positions_m,
                                                              Eigen::Index size,
                                                              Eigen::Index cluster,
                                                              std::uint64_t seed);

/// Maximises the REML likelihood of `values` at `positions_m` over the length scales, the
/// signal sd and the nugget (bounded below by options.noise_sd_m) from options.restarts
/// deterministic starts; `frame` fixes the trend basis.
[[nodiscard]] KrigingAxisFit fit_kriging_axis(const ConstPoints3Ref& positions_m,
                                              const Eigen::VectorXd& values,
                                              const KrigingOptions& options,
                                              const TrendFrame& frame);

}  // namespace vrreg::detail
