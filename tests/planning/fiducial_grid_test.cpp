// SPDX-License-Identifier: Apache-2.0
// The fiducial cube of Procedure 1 (paper section 6): counts, spacing, the part point at the
// centre of a cell, d = sqrt(3)/2 A, and how the half-width is rounded.
#include "vrreg/planning/fiducial_grid.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg::planning {
namespace {

TEST(CubeGeometry, RoundsTheHalfWidthUpToAnOddNumberOfCells) {
  struct Case {
    double s_mm, a_mm, covered_mm;
    int nodes;
  };
  for (const Case c :
       {Case{10, 5, 12.5, 6}, Case{7.5, 5, 7.5, 4}, Case{2.5, 5, 2.5, 2}, Case{1, 5, 2.5, 2},
        Case{12.5, 5, 12.5, 6}, Case{12.6, 5, 17.5, 8}, Case{25, 12.5, 31.25, 6}}) {
    const CubeGeometry g = cube_geometry(c.s_mm * 1e-3, c.a_mm * 1e-3);
    EXPECT_EQ(g.nodes_per_axis, c.nodes) << c.s_mm << " / " << c.a_mm;
    EXPECT_NEAR(g.halfwidth_m, c.covered_mm * 1e-3, 1e-15) << c.s_mm << " / " << c.a_mm;
    EXPECT_GE(g.halfwidth_m, g.requested_halfwidth_m - 1e-12);
    EXPECT_EQ((g.nodes_per_axis - 1) % 2, 1) << "odd number of cells";
    EXPECT_EQ(g.n_nodes(), static_cast<long long>(c.nodes) * c.nodes * c.nodes);
  }
  // A half-width that is a half-odd multiple of A up to rounding is not rounded up.
  EXPECT_EQ(cube_geometry(0.0075 * (1 + 1e-13), 0.005).nodes_per_axis, 4);
  EXPECT_EQ(cube_geometry(0.015 / 2.0, 0.005).nodes_per_axis, 4);
}

TEST(CubeGeometry, NodesFillTheCubeWithSpacingAAroundThePartPoint) {
  const Eigen::Vector3d part(0.45, -0.1, 0.25);
  const CubeGeometry g = cube_geometry(0.010, 0.005);
  const Points3 nodes = cube_nodes(g, part);
  ASSERT_EQ(nodes.cols(), 216);
  // Centred on the part point, spanning +-S' on every axis.
  EXPECT_EIGEN_NEAR(Eigen::Vector3d(nodes.rowwise().mean()), part, 1e-15);
  EXPECT_EIGEN_NEAR(Eigen::Vector3d((nodes.colwise() - part).rowwise().maxCoeff()),
                    Eigen::Vector3d::Constant(0.0125), 1e-15);
  EXPECT_EIGEN_NEAR(Eigen::Vector3d((nodes.colwise() - part).rowwise().minCoeff()),
                    Eigen::Vector3d::Constant(-0.0125), 1e-15);
  // Column ix + n (iy + n iz) is node (ix, iy, iz); neighbours along each axis are A apart.
  const int n = g.nodes_per_axis;
  for (int iz = 0; iz < n; ++iz) {
    for (int iy = 0; iy < n; ++iy) {
      for (int ix = 0; ix < n; ++ix) {
        const Eigen::Vector3d p = nodes.col(ix + n * (iy + n * iz));
        EXPECT_EIGEN_NEAR(p, cube_node(g, part, {ix, iy, iz}), 0.0);
        if (ix + 1 < n) {
          EXPECT_NEAR((cube_node(g, part, {ix + 1, iy, iz}) - p).norm(), 0.005, 1e-15);
        }
      }
    }
  }
}

TEST(CubeGeometry, TargetAtACellCentreWithEightNearestFiducialsAtSqrt3HalfA) {
  const Eigen::Vector3d part(0.4, 0.2, 0.3);
  for (const double s : {0.0025, 0.0075, 0.010, 0.020}) {
    const CubeGeometry g = cube_geometry(s, 0.005);
    const Points3 nodes = cube_nodes(g, part);
    std::vector<double> d(static_cast<std::size_t>(nodes.cols()));
    for (Eigen::Index c = 0; c < nodes.cols(); ++c) {
      d[static_cast<std::size_t>(c)] = (nodes.col(c) - part).norm();
    }
    std::sort(d.begin(), d.end());
    EXPECT_NEAR(g.d_min_m(), std::sqrt(3.0) / 2.0 * 0.005, 1e-15);
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(d[static_cast<std::size_t>(k)], g.d_min_m(), 1e-12);
    if (d.size() > 8) {
      EXPECT_GT(d[8], g.d_min_m() + 1e-6);
    }
    EXPECT_NEAR(d.back(), g.d_max_m(), 1e-12);
  }
}

TEST(CubeGeometry, BadInputThrows) {
  EXPECT_THROW(cube_geometry(0.0, 0.005), InputError);
  EXPECT_THROW(cube_geometry(0.01, -0.005), InputError);
  EXPECT_THROW(cube_geometry(NAN, 0.005), InputError);
  EXPECT_THROW(cube_geometry(0.01, INFINITY), InputError);
  EXPECT_THROW(cube_geometry(1.0, 1e-6), InputError);  // a million nodes per axis
}

}  // namespace
}  // namespace vrreg::planning
