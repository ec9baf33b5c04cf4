// SPDX-License-Identifier: Apache-2.0
// Grid detection: per-axis coordinate levels on an evenly spaced lattice, then the base lattice
// or the finest complete every-s-th sub-lattice (the paper's A1/A2 layouts: a full grid minus
// the targets, whose fiducials hold a complete grid of twice the spacing).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <tuple>
#include <unordered_map>

#include "lattice.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/grid.hpp"

namespace vrreg {
namespace {

constexpr std::int64_t kMaxNodeChecks = 50'000'000;  // sub-lattice search budget

// A lattice holds at least 1 node in 1000, or it is refused before any search. What this admits:
// a complete every-s-th sub-lattice from end to end of its lattice holds c of the (c - 1) s + 1
// levels per axis (>= 1/s), so >= 1/s^3 of the nodes: every stride up to 10 is found even with
// nothing else on the lattice, and any lattice with up to 99.9 % of its nodes empty is searched.
// The paper's layouts: A1, A2 and the example cell hold 89-92 % of their nodes; dataset B (cube
// corners of 5-50 mm edges around each target) holds 1 in 112 of its 2.5 mm lattice and keeps its
// every-10th grid of 25 mm. What it refuses: points at free positions, whose levels match a
// lattice of their last written digit or of any spacing under twice the tolerance (~10^16 nodes
// for 700 fiducials in mm with 3 decimals). It also bounds the search: at most (1000 n)^(1/3)
// strides, each looking once at the fiducials and the occupied levels.
constexpr std::int64_t kMaxLatticeNodesPerFiducial = 1000;

/// Per offset o < stride: how many levels o, o + s, ... the axis has if there are >= 2 and all
/// are occupied, else 0.
std::vector<int> axis_offset_counts(const detail::AxisLattice& axis, int stride) {
  std::vector<int> out(static_cast<std::size_t>(stride), 0);
  for (int offset = 0; offset < stride && offset < axis.size(); ++offset) {
    const int count = (axis.size() - 1 - offset) / stride + 1;
    if (count < 2) continue;
    bool all = true;
    for (int m = 0; m < count && all; ++m) {
      all = axis.occupied[static_cast<std::size_t>(offset + m * stride)] != 0;
    }
    if (all) out[static_cast<std::size_t>(offset)] = count;
  }
  return out;
}

std::string describe_lattice(const std::array<detail::AxisLattice, 3>& axes,
                             std::size_t n_fiducials) {
  std::ostringstream out;
  out << "the " << axes[0].size() << " x " << axes[1].size() << " x " << axes[2].size()
      << " lattice of " << units::m_to_mm(axes[0].spacing_m) << " x "
      << units::m_to_mm(axes[1].spacing_m) << " x " << units::m_to_mm(axes[2].spacing_m)
      << " mm holds " << n_fiducials << " fiducials on "
      << std::int64_t{axes[0].size()} * axes[1].size() * axes[2].size() << " nodes";
  return out.str();
}

}  // namespace

GridDetection detect_grid(const ConstPoints3Ref& fiducials_robot_m, double tolerance_m) {
  GridDetection out;
  if (fiducials_robot_m.cols() < 8 || !fiducials_robot_m.allFinite() ||
      !(tolerance_m > 0.0 && std::isfinite(tolerance_m))) {
    out.reason = "a grid needs at least 8 finite fiducials and a tolerance > 0";
    return out;
  }
  auto lattice = detail::fit_lattice(fiducials_robot_m, tolerance_m, out.reason);
  if (!lattice) return out;
  const std::array<detail::AxisLattice, 3>& axes = lattice->axes;
  const std::unordered_map<std::int64_t, Eigen::Index>& node_fiducial = lattice->node_fiducial;
  const std::int64_t nx = axes[0].size();
  const std::int64_t ny = axes[1].size();
  const std::int64_t n_nodes = nx * ny * axes[2].size();  // <= 2^60: levels per axis <= 2^20
  if (n_nodes > kMaxLatticeNodesPerFiducial * fiducials_robot_m.cols()) {
    std::ostringstream why;
    why << describe_lattice(axes, node_fiducial.size()) << ", fewer than 1 in "
        << kMaxLatticeNodesPerFiducial << ": scattered, not a grid";
    out.reason = why.str();
    return out;
  }
  // The occupied nodes as bits (<= 1000 n nodes: <= 16 n words), and the fiducials' nodes by
  // their largest index (a counting sort): a stride-s sub-lattice starts at a node with all
  // indices < s, so each stride looks only at those, never at every offset triple (s^3 of them).
  const int max_stride = std::min({axes[0].size(), axes[1].size(), axes[2].size()}) - 1;
  std::vector<std::uint64_t> occupied(static_cast<std::size_t>((n_nodes + 63) / 64), 0);
  std::vector<std::size_t> reach_end(static_cast<std::size_t>(max_stride) + 1, 0);
  const auto node_index = [&](std::int64_t key) {
    return std::array{static_cast<int>(key % nx), static_cast<int>((key / nx) % ny),
                      static_cast<int>(key / (nx * ny))};
  };
  for (const auto& [key, column] : node_fiducial) {
    occupied[static_cast<std::size_t>(key >> 6)] |= std::uint64_t{1} << (key & 63);
    const auto [i, j, k] = node_index(key);
    const int reach = std::max({i, j, k});
    if (reach < max_stride) ++reach_end[static_cast<std::size_t>(reach) + 1];
  }
  std::partial_sum(reach_end.begin(), reach_end.end(), reach_end.begin());
  std::vector<std::array<int, 3>> by_reach(reach_end.back());
  {
    std::vector<std::size_t> next(reach_end.begin(), reach_end.end() - 1);
    for (const auto& [key, column] : node_fiducial) {
      const std::array<int, 3> index = node_index(key);
      const int reach = std::max({index[0], index[1], index[2]});
      if (reach < max_stride) by_reach[next[static_cast<std::size_t>(reach)]++] = index;
    }
  }
  const auto complete = [&](std::array<int, 3> offset, std::array<int, 3> count, int stride,
                            std::int64_t& budget) {
    for (int k = 0; k < count[2]; ++k) {
      for (int j = 0; j < count[1]; ++j) {
        for (int i = 0; i < count[0]; ++i) {
          if (--budget < 0) return false;
          const std::int64_t key = (offset[0] + i * stride) +
                                   nx * ((offset[1] + j * stride) + ny * (offset[2] + k * stride));
          if (((occupied[static_cast<std::size_t>(key >> 6)] >> (key & 63)) & 1U) == 0) {
            return false;
          }
        }
      }
    }
    return true;
  };
  std::int64_t budget = kMaxNodeChecks;
  std::vector<std::tuple<std::int64_t, std::array<int, 3>, std::array<int, 3>>> candidates;
  for (int stride = 1; stride <= max_stride && budget > 0; ++stride) {
    const auto cx = axis_offset_counts(axes[0], stride);
    const auto cy = axis_offset_counts(axes[1], stride);
    const auto cz = axis_offset_counts(axes[2], stride);
    // Candidates with the most nodes first, then the smallest offsets.
    candidates.clear();
    for (std::size_t f = 0; f < reach_end[static_cast<std::size_t>(stride)]; ++f) {
      const auto [i, j, k] = by_reach[f];
      const std::int64_t total = std::int64_t{cx[static_cast<std::size_t>(i)]} *
                                 cy[static_cast<std::size_t>(j)] * cz[static_cast<std::size_t>(k)];
      if (total == 0 || total > fiducials_robot_m.cols()) continue;
      candidates.emplace_back(
          -total, std::array{i, j, k},
          std::array{cx[static_cast<std::size_t>(i)], cy[static_cast<std::size_t>(j)],
                     cz[static_cast<std::size_t>(k)]});
    }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [neg_total, offset, count] : candidates) {
      if (!complete(offset, count, stride, budget)) continue;
      GridLayout grid;
      grid.stride = stride;
      grid.nodes = count;
      grid.n_fiducials = fiducials_robot_m.cols();
      for (std::size_t a = 0; a < 3; ++a) {
        grid.origin_m(static_cast<Eigen::Index>(a)) =
            axes[a].origin_m + offset[a] * axes[a].spacing_m;
        grid.spacing_m(static_cast<Eigen::Index>(a)) = stride * axes[a].spacing_m;
      }
      grid.fiducial.reserve(static_cast<std::size_t>(-neg_total));
      for (int k = 0; k < count[2]; ++k) {
        for (int j = 0; j < count[1]; ++j) {
          for (int i = 0; i < count[0]; ++i) {
            grid.fiducial.push_back(
                node_fiducial.at((offset[0] + i * stride) +
                                 nx * ((offset[1] + j * stride) + ny * (offset[2] + k * stride))));
          }
        }
      }
      out.grid = std::move(grid);
      return out;
    }
  }
  std::ostringstream why;
  why << describe_lattice(axes, node_fiducial.size())
      << ", and no every-s-th sub-lattice is complete";
  if (budget <= 0) why << " (search stopped after " << kMaxNodeChecks << " node checks)";
  out.reason = why.str();
  return out;
}

}  // namespace vrreg
