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

/// `size` distinct indices of 0..n-1 (all of them if size >= n), increasing, drawn uniformly
/// by a seeded splitmix64 Fisher-Yates: same seed, same subset on every platform. Uniform
/// rather than spatially thinned so that the subset keeps the short pair distances that
/// separate the nugget from the length scales.
[[nodiscard]] std::vector<Eigen::Index> seeded_subset(Eigen::Index n, Eigen::Index size,
                                                      std::uint64_t seed);

/// Maximises the REML likelihood of `values` at `positions_m` over the length scales, the
/// signal sd and the nugget (bounded below by options.noise_sd_m) from options.restarts
/// deterministic starts; `frame` fixes the trend basis.
[[nodiscard]] KrigingAxisFit fit_kriging_axis(const ConstPoints3Ref& positions_m,
                                              const Eigen::VectorXd& values,
                                              const KrigingOptions& options,
                                              const TrendFrame& frame);

}  // namespace vrreg::detail
