// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/cube_tour.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "vrreg/core/check.hpp"

namespace vrreg::planning {
namespace {

constexpr int kMaxStarts = 64;
constexpr int kMaxTwoOptPasses = 100;
constexpr double kImprovement = 1e-12;  // [m]: smaller gains are rounding

struct Problem {
  const ConstPoints3Ref& centres;
  Points3 entry;  // distinct (entry, exit) pairs only
  Points3 exit;
  std::vector<int> variant;  // the first variant index with that pair
};

Problem make_problem(const ConstPoints3Ref& centres, const ConstPoints3Ref& entry,
                     const ConstPoints3Ref& exit) {
  VRREG_THROW_UNLESS(centres.cols() > 0, "cube tour: no cubes");
  VRREG_THROW_UNLESS(entry.cols() > 0 && entry.cols() == exit.cols(),
                     "cube tour: need as many entry as exit offsets (at least one), got "
                         << entry.cols() << " and " << exit.cols());
  Problem p{centres, Points3(3, 0), Points3(3, 0), {}};
  std::vector<Eigen::Index> kept;
  for (Eigen::Index v = 0; v < entry.cols(); ++v) {
    const bool seen = std::any_of(kept.begin(), kept.end(), [&](Eigen::Index k) {
      return entry.col(k) == entry.col(v) && exit.col(k) == exit.col(v);
    });
    if (!seen) kept.push_back(v);
  }
  p.entry.resize(3, static_cast<Eigen::Index>(kept.size()));
  p.exit.resize(3, static_cast<Eigen::Index>(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) {
    p.entry.col(static_cast<Eigen::Index>(k)) = entry.col(kept[k]);
    p.exit.col(static_cast<Eigen::Index>(k)) = exit.col(kept[k]);
    p.variant.push_back(static_cast<int>(kept[k]));
  }
  return p;
}

double centre_distance(const Problem& p, int a, int b) {
  return (p.centres.col(a) - p.centres.col(b)).norm();
}

// Exact choice of every cube's (entry, exit) pair for a fixed order: Viterbi over the pairs.
double best_variants(const Problem& p, const std::vector<int>& order, std::vector<int>& variant) {
  const std::size_t m = order.size();
  const auto n_pairs = static_cast<std::size_t>(p.entry.cols());
  std::vector<double> cost(n_pairs, 0.0);
  std::vector<double> next(n_pairs);
  std::vector<std::size_t> back(m * n_pairs, 0);
  for (std::size_t k = 1; k < m; ++k) {
    const Eigen::Vector3d from = p.centres.col(order[k - 1]);
    const Eigen::Vector3d to = p.centres.col(order[k]);
    for (std::size_t v = 0; v < n_pairs; ++v) {
      const Eigen::Vector3d entry = to + p.entry.col(static_cast<Eigen::Index>(v));
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t u = 0; u < n_pairs; ++u) {
        const double c = cost[u] + (from + p.exit.col(static_cast<Eigen::Index>(u)) - entry).norm();
        if (c < best) {
          best = c;
          back[k * n_pairs + v] = u;
        }
      }
      next[v] = best;
    }
    cost.swap(next);
  }
  std::size_t v =
      static_cast<std::size_t>(std::min_element(cost.begin(), cost.end()) - cost.begin());
  const double total = cost[v];
  variant.assign(m, 0);
  for (std::size_t k = m; k-- > 0;) {
    variant[k] = p.variant[v];
    v = back[k * n_pairs + v];
  }
  return total;
}

std::vector<int> nearest_neighbour(const Problem& p, int start) {
  const auto m = static_cast<int>(p.centres.cols());
  std::vector<int> order{start};
  std::vector<bool> used(static_cast<std::size_t>(m), false);
  used[static_cast<std::size_t>(start)] = true;
  for (int k = 1; k < m; ++k) {
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (int c = 0; c < m; ++c) {
      if (used[static_cast<std::size_t>(c)]) continue;
      const double d = centre_distance(p, order.back(), c);
      if (d < best_d) {
        best_d = d;
        best = c;
      }
    }
    used[static_cast<std::size_t>(best)] = true;
    order.push_back(best);
  }
  return order;
}

// 2-opt on an open path over the centres: reverse order[i..j] while that shortens the path.
void two_opt(const Problem& p, std::vector<int>& order) {
  const std::size_t m = order.size();
  for (int pass = 0; pass < kMaxTwoOptPasses; ++pass) {
    bool improved = false;
    for (std::size_t i = 0; i + 1 < m; ++i) {
      for (std::size_t j = i + 1; j < m; ++j) {
        double delta = 0.0;
        if (i > 0) {
          delta += centre_distance(p, order[i - 1], order[j]) -
                   centre_distance(p, order[i - 1], order[i]);
        }
        if (j + 1 < m) {
          delta += centre_distance(p, order[i], order[j + 1]) -
                   centre_distance(p, order[j], order[j + 1]);
        }
        if (delta < -kImprovement) {
          std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i),
                       order.begin() + static_cast<std::ptrdiff_t>(j) + 1);
          improved = true;
        }
      }
    }
    if (!improved) break;
  }
}

}  // namespace

CubeTour plan_cube_tour(const ConstPoints3Ref& centres_m, const ConstPoints3Ref& entry_offsets_m,
                        const ConstPoints3Ref& exit_offsets_m) {
  const Problem p = make_problem(centres_m, entry_offsets_m, exit_offsets_m);
  const auto m = static_cast<int>(centres_m.cols());
  CubeTour best;
  best.order.resize(static_cast<std::size_t>(m));
  std::iota(best.order.begin(), best.order.end(), 0);
  best.between_cubes_m = best_variants(p, best.order, best.variant);
  std::vector<int> variant;
  for (int start = 0; start < std::min(m, kMaxStarts); ++start) {
    std::vector<int> order = nearest_neighbour(p, start);
    two_opt(p, order);
    const double cost = best_variants(p, order, variant);
    if (cost < best.between_cubes_m - kImprovement) {
      best.order = order;
      best.variant = variant;
      best.between_cubes_m = cost;
    }
  }
  return best;
}

double between_cube_travel_m(const ConstPoints3Ref& centres_m,
                             const ConstPoints3Ref& entry_offsets_m,
                             const ConstPoints3Ref& exit_offsets_m, const std::vector<int>& order,
                             const std::vector<int>& variant) {
  VRREG_THROW_UNLESS(
      order.size() == variant.size(),
      "cube travel: " << order.size() << " cubes but " << variant.size() << " variants");
  VRREG_THROW_UNLESS(entry_offsets_m.cols() == exit_offsets_m.cols(),
                     "cube travel: entry and exit offsets differ in number");
  double total = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    VRREG_THROW_UNLESS(order[k] >= 0 && order[k] < centres_m.cols() && variant[k] >= 0 &&
                           variant[k] < entry_offsets_m.cols(),
                       "cube travel: cube or variant index out of range at step " << k);
    if (k == 0) continue;
    total += (centres_m.col(order[k - 1]) + exit_offsets_m.col(variant[k - 1]) -
              centres_m.col(order[k]) - entry_offsets_m.col(variant[k]))
                 .norm();
  }
  return total;
}

}  // namespace vrreg::planning
