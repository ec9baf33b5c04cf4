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

/// Offsets o < s whose levels o, o + s, ... (>= 2 of them) are all occupied, with their counts.
std::vector<std::pair<int, int>> axis_offsets(const detail::AxisLattice& axis, int stride) {
  std::vector<std::pair<int, int>> out;
  for (int offset = 0; offset < stride; ++offset) {
    const int count = (axis.size() - 1 - offset) / stride + 1;
    if (offset >= axis.size() || count < 2) continue;
    bool all = true;
    for (int m = 0; m < count && all; ++m) {
      all = axis.occupied[static_cast<std::size_t>(offset + m * stride)] != 0;
    }
    if (all) out.emplace_back(offset, count);
  }
  return out;
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
  const auto complete = [&](std::array<int, 3> offset, std::array<int, 3> count, int stride,
                            std::int64_t& budget) {
    for (int k = 0; k < count[2]; ++k) {
      for (int j = 0; j < count[1]; ++j) {
        for (int i = 0; i < count[0]; ++i) {
          if (--budget < 0) return false;
          const std::int64_t key = (offset[0] + i * stride) +
                                   nx * ((offset[1] + j * stride) + ny * (offset[2] + k * stride));
          if (!node_fiducial.contains(key)) return false;
        }
      }
    }
    return true;
  };
  const int max_stride = std::min({axes[0].size(), axes[1].size(), axes[2].size()}) - 1;
  std::int64_t budget = kMaxNodeChecks;
  for (int stride = 1; stride <= max_stride && budget > 0; ++stride) {
    const auto ox = axis_offsets(axes[0], stride);
    const auto oy = axis_offsets(axes[1], stride);
    const auto oz = axis_offsets(axes[2], stride);
    // Candidates with the most nodes first, then the smallest offsets.
    std::vector<std::tuple<std::int64_t, std::array<int, 3>, std::array<int, 3>>> candidates;
    for (const auto& x : ox) {
      for (const auto& y : oy) {
        for (const auto& z : oz) {
          const std::int64_t total = std::int64_t{x.second} * y.second * z.second;
          if (total > fiducials_robot_m.cols()) continue;
          candidates.emplace_back(-total, std::array{x.first, y.first, z.first},
                                  std::array{x.second, y.second, z.second});
        }
      }
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
  why << "the " << axes[0].size() << " x " << axes[1].size() << " x " << axes[2].size()
      << " lattice of " << units::m_to_mm(axes[0].spacing_m) << " x "
      << units::m_to_mm(axes[1].spacing_m) << " x " << units::m_to_mm(axes[2].spacing_m)
      << " mm holds " << node_fiducial.size() << " fiducials on " << nx * ny * axes[2].size()
      << " nodes, and no every-s-th sub-lattice is complete";
  if (budget <= 0) why << " (search stopped after " << kMaxNodeChecks << " node checks)";
  out.reason = why.str();
  return out;
}

}  // namespace vrreg
