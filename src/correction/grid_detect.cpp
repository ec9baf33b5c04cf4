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

#include "vrreg/core/units.hpp"
#include "vrreg/correction/grid.hpp"

namespace vrreg {
namespace {

constexpr std::int64_t kMaxLevels = 1 << 20;         // base-lattice levels per axis
constexpr std::int64_t kMaxNodeChecks = 50'000'000;  // sub-lattice search budget
const char* const kAxisName[3] = {"x", "y", "z"};

/// Evenly spaced levels of one axis: level k at origin_m + k spacing_m, `occupied[k]` if any
/// fiducial has that coordinate.
struct AxisLattice {
  double origin_m = 0.0;
  double spacing_m = 0.0;
  std::vector<char> occupied;
  [[nodiscard]] int size() const { return static_cast<int>(occupied.size()); }
};

std::optional<AxisLattice> fit_axis(const ConstPoints3Ref& points_m, int axis, double tolerance_m,
                                    std::string& reason) {
  std::vector<double> values(static_cast<std::size_t>(points_m.cols()));
  for (Eigen::Index j = 0; j < points_m.cols(); ++j) {
    values[static_cast<std::size_t>(j)] = points_m(axis, j);
  }
  std::sort(values.begin(), values.end());
  std::vector<double> levels;  // cluster means: a new level after a gap > tolerance
  std::size_t start = 0;
  for (std::size_t i = 1; i <= values.size(); ++i) {
    if (i == values.size() || values[i] - values[i - 1] > tolerance_m) {
      const double sum = std::accumulate(values.begin() + static_cast<std::ptrdiff_t>(start),
                                         values.begin() + static_cast<std::ptrdiff_t>(i), 0.0);
      levels.push_back(sum / static_cast<double>(i - start));
      start = i;
    }
  }
  std::ostringstream why;
  if (levels.size() < 2) {
    why << "all fiducials share one " << kAxisName[axis] << " level (a flat layout)";
    reason = why.str();
    return std::nullopt;
  }
  double min_gap = levels[1] - levels[0];
  for (std::size_t i = 2; i < levels.size(); ++i)
    min_gap = std::min(min_gap, levels[i] - levels[i - 1]);
  const double span = levels.back() - levels.front();
  if (span / min_gap > static_cast<double>(kMaxLevels)) {
    why << kAxisName[axis] << " levels span " << span / min_gap << " times their smallest gap";
    reason = why.str();
    return std::nullopt;
  }
  // Least-squares lattice level_i = origin + k_i spacing through the rounded indices k_i.
  std::vector<double> k(levels.size());
  for (std::size_t i = 0; i < levels.size(); ++i)
    k[i] = std::round((levels[i] - levels[0]) / min_gap);
  const double n = static_cast<double>(levels.size());
  const double k_mean = std::accumulate(k.begin(), k.end(), 0.0) / n;
  const double level_mean = std::accumulate(levels.begin(), levels.end(), 0.0) / n;
  double skk = 0.0;
  double skl = 0.0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    skk += (k[i] - k_mean) * (k[i] - k_mean);
    skl += (k[i] - k_mean) * (levels[i] - level_mean);
  }
  AxisLattice lattice;
  lattice.spacing_m = skl / skk;
  lattice.origin_m = level_mean - k_mean * lattice.spacing_m;
  lattice.occupied.assign(static_cast<std::size_t>(k.back()) + 1, 0);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const double off_m = levels[i] - (lattice.origin_m + k[i] * lattice.spacing_m);
    if (std::abs(off_m) > tolerance_m || (i > 0 && k[i] == k[i - 1])) {
      why << kAxisName[axis] << " levels are not evenly spaced: the level at "
          << units::m_to_mm(levels[i]) << " mm is " << units::m_to_mm(off_m) << " mm off a "
          << units::m_to_mm(lattice.spacing_m) << " mm lattice";
      reason = why.str();
      return std::nullopt;
    }
    lattice.occupied[static_cast<std::size_t>(k[i])] = 1;
  }
  return lattice;
}

/// Offsets o < s whose levels o, o + s, ... (>= 2 of them) are all occupied, with their counts.
std::vector<std::pair<int, int>> axis_offsets(const AxisLattice& axis, int stride) {
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
  std::array<AxisLattice, 3> axes;
  for (int axis = 0; axis < 3; ++axis) {
    auto lattice = fit_axis(fiducials_robot_m, axis, tolerance_m, out.reason);
    if (!lattice) return out;
    axes[static_cast<std::size_t>(axis)] = std::move(*lattice);
  }
  const std::int64_t nx = axes[0].size();
  const std::int64_t ny = axes[1].size();
  std::unordered_map<std::int64_t, Eigen::Index> node_fiducial;
  node_fiducial.reserve(static_cast<std::size_t>(fiducials_robot_m.cols()));
  for (Eigen::Index j = 0; j < fiducials_robot_m.cols(); ++j) {
    std::array<std::int64_t, 3> index{};
    for (std::size_t a = 0; a < 3; ++a) {
      const double t = (fiducials_robot_m(static_cast<Eigen::Index>(a), j) - axes[a].origin_m) /
                       axes[a].spacing_m;
      index[a] = std::llround(t);
      // The lattice is fitted to level means: a node may sit a tolerance from its level.
      if (std::abs(t - static_cast<double>(index[a])) * axes[a].spacing_m > 2.0 * tolerance_m) {
        std::ostringstream why;
        why << "fiducial " << j << " is off the grid lattice in " << kAxisName[a];
        out.reason = why.str();
        return out;
      }
    }
    const auto [it, inserted] =
        node_fiducial.emplace(index[0] + nx * (index[1] + ny * index[2]), j);
    if (!inserted) {
      std::ostringstream why;
      why << "fiducials " << it->second << " and " << j << " share grid node (" << index[0] << ", "
          << index[1] << ", " << index[2] << ")";
      out.reason = why.str();
      return out;
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
