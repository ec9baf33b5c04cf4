// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/serpentine.hpp"

#include <limits>

#include "vrreg/core/check.hpp"

namespace vrreg::planning {
namespace {

constexpr std::array<std::array<int, 3>, 6> kAxisOrders{
    {{0, 1, 2}, {1, 0, 2}, {0, 2, 1}, {2, 0, 1}, {1, 2, 0}, {2, 1, 0}}};

void check_n(int n) {
  VRREG_THROW_UNLESS(n >= 1 && n <= 1000,
                     "serpentine: nodes per axis must be in 1..1000, got " << n);
}

// Grid index of step (fast, middle, slow) of the canonical walk, mapped through the variant.
Eigen::Vector3i place(int n, const SerpentineVariant& v, int fast, int middle, int slow) {
  const std::array<int, 3> walk{fast, middle, slow};
  Eigen::Vector3i index;
  for (int k = 0; k < 3; ++k) {
    const int axis = v.axes[static_cast<std::size_t>(k)];
    const int value = walk[static_cast<std::size_t>(k)];
    index(axis) = ((v.start_corner >> axis) & 1) != 0 ? n - 1 - value : value;
  }
  return index;
}

}  // namespace

SerpentineVariant serpentine_variant(int k) {
  VRREG_THROW_UNLESS(k >= 0 && k < kSerpentineVariants,
                     "serpentine variant must be in 0..47, got " << k);
  return {k % 8, kAxisOrders[static_cast<std::size_t>(k / 8)]};
}

std::vector<Eigen::Vector3i> serpentine(int nodes_per_axis, const SerpentineVariant& variant) {
  const int n = nodes_per_axis;
  check_n(n);
  std::vector<Eigen::Vector3i> out;
  out.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n) *
              static_cast<std::size_t>(n));
  long long row = 0;  // rows walked so far: odd rows run the fast axis backwards
  for (int slow = 0; slow < n; ++slow) {
    for (int m = 0; m < n; ++m) {
      const int middle = slow % 2 == 0 ? m : n - 1 - m;
      for (int f = 0; f < n; ++f) {
        const int fast = row % 2 == 0 ? f : n - 1 - f;
        out.push_back(place(n, variant, fast, middle, slow));
      }
      ++row;
    }
  }
  return out;
}

std::array<Eigen::Vector3i, 2> serpentine_ends(int nodes_per_axis,
                                               const SerpentineVariant& variant) {
  const int n = nodes_per_axis;
  check_n(n);
  const long long rows = static_cast<long long>(n) * n;
  const int last_fast = (rows - 1) % 2 == 0 ? n - 1 : 0;
  const int last_middle = (n - 1) % 2 == 0 ? n - 1 : 0;
  return {place(n, variant, 0, 0, 0), place(n, variant, last_fast, last_middle, n - 1)};
}

std::size_t insert_centre(std::vector<Eigen::Vector3i>& path, int nodes_per_axis) {
  check_n(nodes_per_axis);
  VRREG_THROW_UNLESS(path.size() >= 2, "insert centre: the path needs at least two nodes");
  const double middle = (nodes_per_axis - 1) / 2.0;
  const auto from_centre = [&](const Eigen::Vector3i& index) {
    return (index.cast<double>().array() - middle).matrix().norm();
  };
  std::size_t best = 1;
  double best_detour = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < path.size(); ++k) {
    const double detour = from_centre(path[k - 1]) + from_centre(path[k]) -
                          (path[k] - path[k - 1]).cast<double>().norm();
    if (detour < best_detour - 1e-12) {
      best_detour = detour;
      best = k;
    }
  }
  path.insert(path.begin() + static_cast<std::ptrdiff_t>(best), kCentreIndex);
  return best;
}

}  // namespace vrreg::planning
