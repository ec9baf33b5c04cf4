// SPDX-License-Identifier: Apache-2.0
#include "kriging_fit.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "bfgs_box.hpp"
#include "kriging_reml.hpp"
#include "point_index.hpp"

namespace vrreg::detail {
namespace kriging_fit {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31U);
}

/// The scan that picks the optimiser's starts: every combination of these length scales per
/// axis (fractions of the fiducials' extent) and nugget excesses (value sds). Starting all
/// axes at one length (as a single start would) misses optima where one axis is much shorter
/// than the others: on the simulated UR5 cells the tangential error varies over millimetres of
/// azimuth but stays constant over the whole height.
constexpr std::array<double, 3> kScanLengths = {0.02, 0.15, 1.0};
constexpr std::array<double, 2> kScanNuggets = {0.2, 0.6};

}  // namespace kriging_fit

std::vector<Eigen::Index> seeded_cluster_subset(const ConstPoints3Ref& positions_m,
                                                Eigen::Index size, Eigen::Index cluster,
                                                std::uint64_t seed) {
  const Eigen::Index n = positions_m.cols();
  std::vector<Eigen::Index> shuffled(static_cast<std::size_t>(n));
  std::iota(shuffled.begin(), shuffled.end(), Eigen::Index{0});
  if (size >= n) return shuffled;  // all of them, in order
  // Cluster centres in the order of a seeded Fisher-Yates shuffle of all fiducials.
  std::uint64_t state = seed;
  for (std::size_t i = shuffled.size(); i > 1; --i) {
    const std::size_t pick = kriging_fit::splitmix64(state) % i;
    std::swap(shuffled[i - 1], shuffled[pick]);
  }
  const PointIndex index(positions_m);
  std::vector<char> taken(static_cast<std::size_t>(n), 0);
  std::vector<Eigen::Index> out;
  out.reserve(static_cast<std::size_t>(size));
  for (const Eigen::Index centre : shuffled) {
    if (static_cast<Eigen::Index>(out.size()) >= size) break;
    if (taken[static_cast<std::size_t>(centre)] != 0) continue;
    for (const Eigen::Index j :
         index.nearest_k(positions_m.col(centre), static_cast<std::size_t>(cluster))) {
      if (static_cast<Eigen::Index>(out.size()) >= size) break;
      if (taken[static_cast<std::size_t>(j)] != 0) continue;
      taken[static_cast<std::size_t>(j)] = 1;
      out.push_back(j);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

KrigingAxisFit fit_kriging_axis(const ConstPoints3Ref& positions_m, const Eigen::VectorXd& values,
                                const KrigingOptions& options, const TrendFrame& frame) {
  // Work in units of the values' sd so that the bounds and tolerances are scale-free.
  const double centred_sd =
      std::sqrt((values.array() - values.mean()).square().mean());
  const double scale = centred_sd > 0.0 ? centred_sd : 1.0;
  const double floor_sd = options.noise_sd_m.value_or(0.0) / scale;
  const Eigen::MatrixXd trend = trend_basis(positions_m, options.trend_degree, frame);
  const RemlData data = make_reml_data(positions_m, values / scale, trend, options.kernel,
                                       floor_sd * floor_sd);
  const auto n = static_cast<double>(values.size());
  const BoxObjective objective = [&](const Eigen::VectorXd& x, Eigen::VectorXd* gradient) {
    RemlParameters g;
    const double value = restricted_log_likelihood(data, x, gradient != nullptr ? &g : nullptr);
    if (gradient != nullptr) {
      *gradient = -g / n;
    }
    return std::isfinite(value) ? -value / n : std::numeric_limits<double>::infinity();
  };
  const double extent_m = frame.scale_m;
  Eigen::VectorXd lower(5);
  Eigen::VectorXd upper(5);
  const double log_extent = std::log(extent_m);
  // Lengths from 1/100 to 20 extents; signal sd 1e-3..1e2 value sds; nugget excess down to
  // 1e-4 value sd (keeps K well conditioned, e.g. for coincident fiducials).
  lower << Eigen::Vector3d::Constant(log_extent + std::log(0.01)), std::log(1e-3), std::log(1e-4);
  upper << Eigen::Vector3d::Constant(log_extent + std::log(20.0)), std::log(1e2), std::log(10.0);

  KrigingAxisFit fit;
  fit.n_fit = values.size();
  // Scan the REML value (no gradient) on a grid of starts, then run the optimiser from the
  // `restarts` best; the grid, the ranking (ties by grid order) and so the result are
  // deterministic. The starts run in parallel (with the three axes: 6 tasks balance 2 cores
  // better than 3); the best is picked in start order, so the result does not depend on
  // scheduling.
  std::vector<Eigen::VectorXd> grid;
  for (const double lx : kriging_fit::kScanLengths) {
    for (const double ly : kriging_fit::kScanLengths) {
      for (const double lz : kriging_fit::kScanLengths) {
        for (const double nugget : kriging_fit::kScanNuggets) {
          Eigen::VectorXd x0(5);
          x0 << log_extent + std::log(lx), log_extent + std::log(ly), log_extent + std::log(lz),
              0.0, std::log(nugget);
          grid.push_back(x0);
        }
      }
    }
  }
  std::vector<double> grid_value(grid.size());
  tbb::parallel_for(std::size_t{0}, grid.size(),
                    [&](std::size_t k) { grid_value[k] = objective(grid[k], nullptr); });
  std::vector<std::size_t> order(grid.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return grid_value[a] < grid_value[b];  // +inf (not positive definite) last
  });
  const int starts = std::clamp(options.restarts, 1, static_cast<int>(grid.size()));
  fit.evaluations += static_cast<int>(grid.size());
  std::vector<BoxMinimum> results(static_cast<std::size_t>(starts));
  tbb::parallel_for(0, starts, [&](int start) {
    results[static_cast<std::size_t>(start)] =
        minimise_bfgs_box(objective, grid[order[static_cast<std::size_t>(start)]], lower, upper,
                          options.max_iterations, 1e-6);
  });
  BoxMinimum best;
  best.value = std::numeric_limits<double>::infinity();
  for (const BoxMinimum& result : results) {
    fit.evaluations += result.evaluations;
    if (result.value < best.value) {
      best = result;
    }
  }
  if (!std::isfinite(best.value)) {
    fit.restricted_log_likelihood = -std::numeric_limits<double>::infinity();
    return fit;  // caller reports: no start had a positive-definite covariance
  }
  KrigingHyperparameters hyper = hyperparameters_from(best.x, floor_sd * floor_sd);
  hyper.signal_sd_m *= scale;
  hyper.nugget_sd_m *= scale;
  fit.hyperparameters = hyper;
  fit.restricted_log_likelihood =
      -best.value * n - static_cast<double>(values.size() - trend.cols()) * std::log(scale);
  return fit;
}

}  // namespace vrreg::detail
