// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/fiducial_grid.hpp"

#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg::planning {
namespace {

constexpr int kMaxNodesPerAxis = 1000;
// S that is a half-odd multiple of A up to rounding (e.g. 7.5 mm / 5 mm) is not rounded up.
constexpr double kRoundingTolerance = 1e-9;

}  // namespace

long long CubeGeometry::n_nodes() const {
  const auto n = static_cast<long long>(nodes_per_axis);
  return n * n * n;
}

double CubeGeometry::d_min_m() const { return std::sqrt(3.0) / 2.0 * spacing_m; }

double CubeGeometry::d_max_m() const { return std::sqrt(3.0) * halfwidth_m; }

CubeGeometry cube_geometry(double halfwidth_m, double spacing_m) {
  VRREG_THROW_UNLESS(
      std::isfinite(halfwidth_m) && halfwidth_m > 0.0,
      "fiducial cube: half-width S must be finite and positive, got " << halfwidth_m << " m");
  VRREG_THROW_UNLESS(
      std::isfinite(spacing_m) && spacing_m > 0.0,
      "fiducial cube: grid spacing A must be finite and positive, got " << spacing_m << " m");
  const double m = std::ceil(halfwidth_m / spacing_m - 0.5 - kRoundingTolerance);
  const double nodes = 2.0 * std::max(m, 0.0) + 2.0;
  VRREG_THROW_UNLESS(nodes <= kMaxNodesPerAxis,
                     "fiducial cube: half-width S = "
                         << halfwidth_m << " m with spacing A = " << spacing_m << " m needs "
                         << nodes << " nodes per axis (at most " << kMaxNodesPerAxis << ")");
  CubeGeometry cube;
  cube.spacing_m = spacing_m;
  cube.requested_halfwidth_m = halfwidth_m;
  cube.nodes_per_axis = static_cast<int>(nodes);
  cube.halfwidth_m = (nodes - 1.0) / 2.0 * spacing_m;
  return cube;
}

Eigen::Vector3d cube_node(const CubeGeometry& cube, const Eigen::Vector3d& centre_m,
                          const Eigen::Vector3i& index) {
  const double middle = (cube.nodes_per_axis - 1) / 2.0;
  return centre_m + cube.spacing_m * (index.cast<double>().array() - middle).matrix();
}

Points3 cube_nodes(const CubeGeometry& cube, const Eigen::Vector3d& centre_m) {
  const int n = cube.nodes_per_axis;
  Points3 nodes(3, static_cast<Eigen::Index>(cube.n_nodes()));
  Eigen::Index column = 0;
  for (int iz = 0; iz < n; ++iz) {
    for (int iy = 0; iy < n; ++iy) {
      for (int ix = 0; ix < n; ++ix) nodes.col(column++) = cube_node(cube, centre_m, {ix, iy, iz});
    }
  }
  return nodes;
}

}  // namespace vrreg::planning
