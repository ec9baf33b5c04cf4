// SPDX-License-Identifier: Apache-2.0
// The evenly spaced lattice of a fiducial layout: per-axis coordinate levels (cluster means),
// a least-squares lattice through them, and each fiducial's node.
#include "lattice.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "vrreg/core/units.hpp"

namespace vrreg::detail {
namespace {

constexpr std::int64_t kMaxLevels = 1 << 20;  // base-lattice levels per axis
const char* const kLatticeAxisName[3] = {"x", "y", "z"};

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
    why << "all fiducials share one " << kLatticeAxisName[axis] << " level (a flat layout)";
    reason = why.str();
    return std::nullopt;
  }
  double min_gap = levels[1] - levels[0];
  for (std::size_t i = 2; i < levels.size(); ++i)
    min_gap = std::min(min_gap, levels[i] - levels[i - 1]);
  const double span = levels.back() - levels.front();
  if (span / min_gap > static_cast<double>(kMaxLevels)) {
    why << kLatticeAxisName[axis] << " levels span " << span / min_gap << " times their smallest gap";
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
      why << kLatticeAxisName[axis] << " levels are not evenly spaced: the level at "
          << units::m_to_mm(levels[i]) << " mm is " << units::m_to_mm(off_m) << " mm off a "
          << units::m_to_mm(lattice.spacing_m) << " mm lattice";
      reason = why.str();
      return std::nullopt;
    }
    lattice.occupied[static_cast<std::size_t>(k[i])] = 1;
  }
  return lattice;
}

}  // namespace

std::optional<FiducialLattice> fit_lattice(const ConstPoints3Ref& fiducials_robot_m,
                                           double tolerance_m, std::string& reason) {
  FiducialLattice out;
  for (int axis = 0; axis < 3; ++axis) {
    auto lattice = fit_axis(fiducials_robot_m, axis, tolerance_m, reason);
    if (!lattice) return std::nullopt;
    out.axes[static_cast<std::size_t>(axis)] = std::move(*lattice);
  }
  out.node_fiducial.reserve(static_cast<std::size_t>(fiducials_robot_m.cols()));
  for (Eigen::Index j = 0; j < fiducials_robot_m.cols(); ++j) {
    std::array<std::int64_t, 3> index{};
    for (std::size_t a = 0; a < 3; ++a) {
      const AxisLattice& axis = out.axes[a];
      const double t = (fiducials_robot_m(static_cast<Eigen::Index>(a), j) - axis.origin_m) /
                       axis.spacing_m;
      index[a] = std::llround(t);
      // The lattice is fitted to level means: a node may sit a tolerance from its level.
      if (std::abs(t - static_cast<double>(index[a])) * axis.spacing_m > 2.0 * tolerance_m) {
        std::ostringstream why;
        why << "fiducial " << j << " is off the grid lattice in " << kLatticeAxisName[a];
        reason = why.str();
        return std::nullopt;
      }
    }
    const auto [it, inserted] =
        out.node_fiducial.emplace(out.key(index[0], index[1], index[2]), j);
    if (!inserted) {
      std::ostringstream why;
      why << "fiducials " << it->second << " and " << j << " share grid node (" << index[0] << ", "
          << index[1] << ", " << index[2] << ")";
      reason = why.str();
      return std::nullopt;
    }
  }
  return out;
}

}  // namespace vrreg::detail
