// SPDX-License-Identifier: Apache-2.0
#pragma once
// Scattered RRBC interpolation: barycentric weights (Eq. 7) in the Delaunay tetrahedron of the
// fiducials' nominal robot positions that holds the registered target (linear precision).
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg {

/// Counters of one point location, for tests and benchmarks.
struct LocateStats {
  int steps = 0;          ///< tetrahedra visited by the walk
  bool fallback = false;  ///< the walk gave up and every tetrahedron was tried
};

/// Point location in the Delaunay tetrahedralization of the fiducials: a walk through
/// neighbouring tetrahedra started next to the nearest fiducial (kd-tree).
class ScatteredStencils {
 public:
  /// fiducials_robot_m: nominal robot positions [m]; tolerance_m: how far outside the hull a
  /// point still counts as inside [m]. Throws InputError for fewer than 4 fiducials, coplanar
  /// fiducials, fiducials sharing a nominal position, or non-finite input.
  ScatteredStencils(const ConstPoints3Ref& fiducials_robot_m, double tolerance_m);
  ~ScatteredStencils();
  ScatteredStencils(ScatteredStencils&&) noexcept;
  ScatteredStencils& operator=(ScatteredStencils&&) noexcept;

  /// Barycentric weights (Eq. 7, size 4) of the tetrahedron holding point_robot_m [m] (the
  /// registered target R T_X + tau); kOutsideHull outside the fiducials' convex hull.
  [[nodiscard]] Stencil stencil(const Eigen::Vector3d& point_robot_m,
                                LocateStats* stats = nullptr) const;
  /// E.g. "scattered, Delaunay of 1167 fiducials: 5421 tetrahedra (310 flat)".
  [[nodiscard]] std::string describe() const;
  [[nodiscard]] std::int64_t n_tetrahedra() const;
  [[nodiscard]] std::int64_t n_flat() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_{};
};

}  // namespace vrreg
