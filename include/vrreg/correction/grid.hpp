// SPDX-License-Identifier: Apache-2.0
#pragma once
// Trilinear RRBC interpolation on a complete regular grid of fiducials (paper Discussion: weights
// of Eq. 7 from a trilinear scheme; 1/8 each at a cell centre).
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg {

/// A complete axis-aligned grid of fiducials in the robot frame: node (i, j, k) sits at
/// origin_m + (i, j, k) .* spacing_m and is fiducial `fiducial[i + nx (j + ny k)]`.
struct GridLayout {
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();   ///< node (0, 0, 0), robot frame [m]
  Eigen::Vector3d spacing_m = Eigen::Vector3d::Ones();  ///< node spacing per axis [m]
  std::array<int, 3> nodes{};                           ///< nodes per axis (>= 2 each)
  int stride = 1;                ///< every stride-th fiducial of the base lattice (1: all of it)
  Eigen::Index n_fiducials = 0;  ///< fiducials the grid was detected in
  std::vector<Eigen::Index> fiducial{};  ///< fiducial column per node, x fastest

  /// Fiducial column of node (i, j, k).
  [[nodiscard]] Eigen::Index node_fiducial(int i, int j, int k) const {
    return fiducial[static_cast<std::size_t>(i + nodes[0] * (j + nodes[1] * k))];
  }
  /// E.g. "grid 6 x 7 x 5 nodes, 50 x 50 x 50 mm (every 2nd fiducial; 210 of 1167 fiducials)".
  [[nodiscard]] std::string describe() const;
};

/// A grid found in a fiducial layout, or why there is none.
struct GridDetection {
  std::optional<GridLayout> grid{};
  std::string reason{};  ///< why no grid was found (empty when found)
};

/// Finds the complete regular grid in fiducials_robot_m [m] (nominal robot positions): the base
/// lattice of the per-axis coordinate levels (each within tolerance_m of an evenly spaced
/// lattice) if every node holds a fiducial, else the finest complete sub-lattice taking every
/// s-th level per axis (s >= 2, common to all axes, any offset; most nodes first). No grid when
/// the lattice holds fewer than 1 node in 1000 (points at free positions).
[[nodiscard]] GridDetection detect_grid(const ConstPoints3Ref& fiducials_robot_m,
                                        double tolerance_m);

/// Trilinear weights (Eq. 7) of the grid cell that holds point_robot_m [m] (the registered
/// target R T_X + tau); status kOutsideGrid beyond tolerance_m [m] outside, not extrapolated here (the corrector does on request).
[[nodiscard]] Stencil grid_stencil(const GridLayout& grid, const Eigen::Vector3d& point_robot_m,
                                   double tolerance_m);

}  // namespace vrreg
