// SPDX-License-Identifier: Apache-2.0
#pragma once
// Delaunay tetrahedralization (qhull, reentrant libqhull_r) for scattered RRBC interpolation.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// Tetrahedra over a point set: vertex columns and, opposite vertex k, the neighbour across
/// face k (-1 on the convex hull). Cospherical input (grids) may give flat tetrahedra.
struct Tetrahedralization {
  std::vector<std::array<Eigen::Index, 4>> vertices{};
  std::vector<std::array<Eigen::Index, 4>> neighbours{};
};

/// Delaunay tetrahedralization of points_m [m] by qhull ("d Qbb Qc Qz Q12 Qt": triangulated,
/// no joggle). Throws InputError for fewer than 4 points, coplanar points, or a qhull failure.
[[nodiscard]] Tetrahedralization delaunay_tetrahedralization(const ConstPoints3Ref& points_m);

}  // namespace vrreg
