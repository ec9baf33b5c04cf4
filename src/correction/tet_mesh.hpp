// SPDX-License-Identifier: Apache-2.0
#pragma once
// Geometry of a Delaunay tetrahedralization for point location: barycentric maps, flat
// tetrahedra, outward hull planes.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/delaunay.hpp"

namespace vrreg::detail {

/// Barycentric coordinates this far below zero still count as on an interior face (roundoff).
inline constexpr double kInteriorRoundoff = 1e-12;

/// One tetrahedron: (l1, l2, l3) = to_bary (q - p0), l0 = 1 - l1 - l2 - l3.
struct TetGeometry {
  Eigen::Matrix3d to_bary = Eigen::Matrix3d::Zero();
  Eigen::Vector3d p0_m = Eigen::Vector3d::Zero();
  /// Plane of face k if it lies on the hull (also when glued to a flat cluster there), else -1.
  std::array<int, 4> hull_plane{-1, -1, -1, -1};
  bool flat = true;  ///< zero volume (cospherical input): never holds a point by itself

  [[nodiscard]] std::array<double, 4> bary(const Eigen::Vector3d& q_m) const {
    const Eigen::Vector3d l = to_bary * (q_m - p0_m);
    return {1.0 - l.sum(), l(0), l(1), l(2)};
  }
};

/// A hull face's plane: normal_out . q - offset_m > 0 outside the hull.
struct HullPlane {
  Eigen::Vector3d normal_out = Eigen::Vector3d::UnitZ();
  double offset_m = 0.0;
  [[nodiscard]] double distance_m(const Eigen::Vector3d& q_m) const {
    return normal_out.dot(q_m) - offset_m;
  }
};

/// The tetrahedralization plus what point location needs.
struct TetMesh {
  Tetrahedralization topology;
  std::vector<TetGeometry> tets;
  std::vector<HullPlane> hull;
  std::vector<Eigen::Index> incident;  ///< a non-flat tetrahedron per point, -1 if none
  Eigen::Index first_solid = -1;
  std::int64_t n_flat = 0;
};

/// Builds the geometry of `topology` over points_m [m].
TetMesh make_tet_mesh(const Points3& points_m, Tetrahedralization topology);

/// The planes of the convex hull of points_m [m] (qhull; coplanar facets merged), outward.
/// Throws InputError when the points span no volume.
std::vector<HullPlane> convex_hull_planes(const ConstPoints3Ref& points_m);

}  // namespace vrreg::detail
