// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: the evenly spaced lattice a fiducial layout sits on (per-axis levels,
// each fiducial's node), shared by the complete-grid detection and the filled lattice.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg::detail {

/// Evenly spaced levels of one axis: level k at origin_m + k spacing_m, `occupied[k]` if any
/// fiducial has that coordinate.
struct AxisLattice {
  double origin_m = 0.0;
  double spacing_m = 0.0;
  std::vector<char> occupied;
  [[nodiscard]] int size() const { return static_cast<int>(occupied.size()); }
};

/// The base lattice of a layout: its three axes and the fiducial at each occupied node, keyed
/// i + nx (j + ny k).
struct FiducialLattice {
  std::array<AxisLattice, 3> axes;
  std::unordered_map<std::int64_t, Eigen::Index> node_fiducial;
  [[nodiscard]] std::int64_t key(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return i + axes[0].size() * (j + std::int64_t{axes[1].size()} * k);
  }
};

/// The lattice of fiducials_robot_m [m] with levels matched to tolerance_m, or nullopt with
/// `reason` (a flat layout, uneven levels, a fiducial off its node, two fiducials on one node).
std::optional<FiducialLattice> fit_lattice(const ConstPoints3Ref& fiducials_robot_m,
                                           double tolerance_m, std::string& reason);

}  // namespace vrreg::detail
