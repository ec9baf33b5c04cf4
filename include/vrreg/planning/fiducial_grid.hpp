// SPDX-License-Identifier: Apache-2.0
#pragma once
// Procedure 1 (paper section 6, Fig. 16): the cube of fiducials measured around one part point.
//
// Geometry: a regular grid of spacing A filling a cube of edge 2S' centred on the part point,
// with the part point (the target) at the centre of the middle grid cell, so that its 8 nearest
// fiducials are the corners of a cube of edge A, at d = sqrt(3)/2 * A (the paper's d, dataset B).
// That needs an odd number of cells per axis, 2S'/A = 2m + 1: the requested half-width S is
// rounded up to the smallest S' = (m + 1/2) * A >= S, so every placement within +-S stays inside
// the grid (trilinear interpolation, Eq. 7, needs the 8 corners of its cell).
#include <Eigen/Core>

#include "vrreg/core/types.hpp"

namespace vrreg::planning {

/// The fiducial cube around one part point (paper section 6): n = 2m + 2 nodes per axis.
struct CubeGeometry {
  double spacing_m = 0.0;              ///< grid spacing A [m]
  double requested_halfwidth_m = 0.0;  ///< the placement tolerance S asked for [m]
  double halfwidth_m = 0.0;            ///< S' = (m + 1/2) * A >= S, the half-width covered [m]
  int nodes_per_axis = 0;              ///< 2m + 2

  /// Fiducials per cube: nodes_per_axis^3.
  [[nodiscard]] long long n_nodes() const;
  /// Target to its 8 nearest fiducials, sqrt(3)/2 * A [m] (the d of Eq. 9).
  [[nodiscard]] double d_min_m() const;
  /// Target to the farthest fiducials (the cube's corners), sqrt(3) * S' [m].
  [[nodiscard]] double d_max_m() const;
};

/// Cube for placement tolerance `halfwidth_m` (S) and grid spacing `spacing_m` (A), S' rounded up
/// as described above; throws InputError unless both are finite and positive and n stays <= 1000.
CubeGeometry cube_geometry(double halfwidth_m, double spacing_m);

/// Position of node `index` (each entry in 0..n-1) of the cube centred on `centre_m` [m]:
/// centre + (index - (n - 1) / 2) * A per axis.
Eigen::Vector3d cube_node(const CubeGeometry& cube, const Eigen::Vector3d& centre_m,
                          const Eigen::Vector3i& index);

/// Every node of the cube, column ix + n * (iy + n * iz) [m].
Points3 cube_nodes(const CubeGeometry& cube, const Eigen::Vector3d& centre_m);

}  // namespace vrreg::planning
