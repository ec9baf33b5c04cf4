// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/grid.hpp"

#include <gtest/gtest.h>

#include "correction_fixtures.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::a1_layout;
using testing::grid_points;
using testing::permuted;
using testing::random_affine_field;
using testing::random_permutation;

using testing::kTolerance;

GridLayout detect_or_fail(const Points3& fiducials) {
  GridDetection d = detect_grid(fiducials, kTolerance);
  EXPECT_TRUE(d.grid.has_value()) << d.reason;
  return d.grid.value_or(GridLayout{});
}

TEST(DetectGrid, FullGridWithDifferentSpacingPerAxis) {
  const Eigen::Vector3d spacing(0.020, 0.025, 0.0125);
  const Eigen::Vector3d origin(0.41, -0.23, 0.105);
  const Points3 fiducials = grid_points(5, 4, 3, spacing, origin);
  const GridLayout grid = detect_or_fail(fiducials);
  EXPECT_EQ(grid.nodes, (std::array<int, 3>{5, 4, 3}));
  EXPECT_EQ(grid.stride, 1);
  EXPECT_EIGEN_NEAR(grid.spacing_m, spacing, 1e-12);
  EXPECT_EIGEN_NEAR(grid.origin_m, origin, 1e-12);
  for (Eigen::Index j = 0; j < fiducials.cols(); ++j)
    EXPECT_EQ(grid.fiducial[static_cast<std::size_t>(j)], j);
  EXPECT_EQ(grid.describe(), "grid 5 x 4 x 3 nodes, 20 x 25 x 12.5 mm");
}

TEST(DetectGrid, A1PatternGivesTheEverySecondSubLattice) {
  const auto a1 = a1_layout();
  ASSERT_EQ(a1.fiducials_robot_m.cols(), 1167);
  const GridLayout grid = detect_or_fail(a1.fiducials_robot_m);
  EXPECT_EQ(grid.nodes, (std::array<int, 3>{6, 7, 5}));
  EXPECT_EQ(grid.stride, 2);
  EXPECT_EIGEN_NEAR(grid.spacing_m, Eigen::Vector3d::Constant(0.05), 1e-12);
  EXPECT_EIGEN_NEAR(grid.origin_m, Eigen::Vector3d(0.3, -0.1, 0.05), 1e-12);
  EXPECT_EQ(grid.describe(),
            "grid 6 x 7 x 5 nodes, 50 x 50 x 50 mm (every 2nd fiducial; 210 of 1167 fiducials)");
  // Every target sits at a cell centre: 8 weights of 1/8, the 8 cube corners at 25 mm.
  for (Eigen::Index t = 0; t < a1.targets_robot_m.cols(); ++t) {
    const Stencil s = grid_stencil(grid, a1.targets_robot_m.col(t), kTolerance);
    ASSERT_EQ(s.status, StencilStatus::kOk);
    ASSERT_EQ(s.size, 8);
    for (std::size_t k = 0; k < 8; ++k) {
      EXPECT_NEAR(s.weight[k], 0.125, 1e-12);
      const Eigen::Vector3d d = a1.fiducials_robot_m.col(s.fiducial[k]) - a1.targets_robot_m.col(t);
      EXPECT_EIGEN_NEAR(d.cwiseAbs(), Eigen::Vector3d::Constant(0.025), 1e-12);
    }
  }
}

TEST(DetectGrid, JitteredNodesWithinTolerance) {
  Random rng(7);
  Points3 fiducials =
      grid_points(6, 5, 4, Eigen::Vector3d(0.025, 0.03, 0.02), Eigen::Vector3d(0.2, 0.1, 0.3));
  for (Eigen::Index j = 0; j < fiducials.cols(); ++j) {
    for (int a = 0; a < 3; ++a) fiducials(a, j) += rng.uniform(-0.4, 0.4) * kTolerance;
  }
  const GridLayout grid = detect_or_fail(fiducials);
  EXPECT_EQ(grid.nodes, (std::array<int, 3>{6, 5, 4}));
  EXPECT_EIGEN_NEAR(grid.spacing_m, Eigen::Vector3d(0.025, 0.03, 0.02), kTolerance);
}

TEST(DetectGrid, RejectsIncompleteLayouts) {
  Points3 full = grid_points(3, 3, 3, Eigen::Vector3d::Constant(0.025));
  const Points3 no_corner = full.rightCols(26);  // node (0,0,0) missing, no sub-lattice avoids it
  const GridDetection d = detect_grid(no_corner, kTolerance);
  EXPECT_FALSE(d.grid);
  EXPECT_NE(d.reason.find("no every-s-th sub-lattice is complete"), std::string::npos) << d.reason;
}

TEST(DetectGrid, RejectsIrregularLayouts) {
  Points3 moved = grid_points(4, 4, 4, Eigen::Vector3d::Constant(0.025));
  moved(0, 21) += 0.003;  // one node 3 mm off in x
  const GridDetection d = detect_grid(moved, kTolerance);
  EXPECT_FALSE(d.grid);
  EXPECT_NE(d.reason.find("not evenly spaced"), std::string::npos) << d.reason;

  Random rng(11);
  EXPECT_FALSE(detect_grid(testing::random_points(rng, 200, 0.1), kTolerance).grid);
  EXPECT_FALSE(detect_grid(grid_points(4, 4, 1, Eigen::Vector3d::Constant(0.02)), kTolerance).grid);

  Points3 twice(3, 16);
  twice << grid_points(2, 2, 2, Eigen::Vector3d::Constant(0.02)),
      grid_points(2, 2, 2, Eigen::Vector3d::Constant(0.02));
  const GridDetection dup = detect_grid(twice, kTolerance);
  EXPECT_FALSE(dup.grid);
  EXPECT_NE(dup.reason.find("share grid node"), std::string::npos) << dup.reason;
}

TEST(GridStencil, WeightsSumToOneAndLieInUnitInterval) {
  Random rng(3);
  const GridLayout grid = detect_or_fail(grid_points(4, 5, 3, Eigen::Vector3d(0.02, 0.025, 0.03)));
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d p(rng.uniform(0, 0.06), rng.uniform(0, 0.1), rng.uniform(0, 0.06));
    const Stencil s = grid_stencil(grid, p, kTolerance);
    ASSERT_EQ(s.status, StencilStatus::kOk);
    double sum = 0.0;
    for (const double w : s.weight) {
      EXPECT_GE(w, 0.0);
      EXPECT_LE(w, 1.0);
      sum += w;
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
  }
}

TEST(GridStencil, ExactAtNodesAndReproducesAffineFields) {
  Random rng(5);
  const Points3 fiducials =
      grid_points(5, 6, 4, Eigen::Vector3d(0.025, 0.02, 0.03), Eigen::Vector3d(0.3, 0.1, -0.2));
  const GridLayout grid = detect_or_fail(fiducials);
  const auto field = random_affine_field(rng);
  const Points3 corrections = field.at(fiducials);
  for (Eigen::Index j = 0; j < fiducials.cols(); ++j) {
    const Stencil s = grid_stencil(grid, fiducials.col(j), kTolerance);
    EXPECT_EIGEN_NEAR(interpolate_correction(s, corrections), corrections.col(j), 1e-15);
  }
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d p =
        Eigen::Vector3d(0.3, 0.1, -0.2) +
        Eigen::Vector3d(rng.uniform(0, 0.1), rng.uniform(0, 0.1), rng.uniform(0, 0.09));
    const Stencil s = grid_stencil(grid, p, kTolerance);
    ASSERT_EQ(s.status, StencilStatus::kOk);
    EXPECT_EIGEN_NEAR(interpolate_correction(s, corrections), field(p), 1e-15);
  }
}

TEST(GridStencil, FlagsPointsOutsideTheGrid) {
  const GridLayout grid = detect_or_fail(grid_points(3, 3, 3, Eigen::Vector3d::Constant(0.05)));
  EXPECT_EQ(grid_stencil(grid, Eigen::Vector3d(0.05, 0.05, 0.1 + 1e-4), kTolerance).status,
            StencilStatus::kOutsideGrid);
  EXPECT_EQ(grid_stencil(grid, Eigen::Vector3d(-1e-3, 0.05, 0.05), kTolerance).status,
            StencilStatus::kOutsideGrid);
  // Within the tolerance of the boundary: clamped onto it.
  const Stencil s =
      grid_stencil(grid, Eigen::Vector3d(0.05, 0.05, 0.1 + 0.5 * kTolerance), kTolerance);
  EXPECT_EQ(s.status, StencilStatus::kOk);
  EXPECT_NEAR(s.weight[4] + s.weight[5] + s.weight[6] + s.weight[7], 1.0, 1e-15);
}

TEST(GridStencil, InvariantToFiducialOrder) {
  Random rng(9);
  const auto a1 = a1_layout();
  const auto order = random_permutation(rng, a1.fiducials_robot_m.cols());
  const Points3 shuffled = permuted(a1.fiducials_robot_m, order);
  const GridLayout grid = detect_or_fail(a1.fiducials_robot_m);
  const GridLayout grid_shuffled = detect_or_fail(shuffled);
  const auto field = random_affine_field(rng);
  Points3 corrections = field.at(a1.fiducials_robot_m);
  corrections += 1e-4 * corrections.array().sin().matrix();  // not affine
  const Points3 corrections_shuffled = permuted(corrections, order);
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Vector3d p =
        Eigen::Vector3d(0.3, -0.1, 0.05) +
        Eigen::Vector3d(rng.uniform(0, 0.25), rng.uniform(0, 0.3), rng.uniform(0, 0.2));
    const Stencil a = grid_stencil(grid, p, kTolerance);
    const Stencil b = grid_stencil(grid_shuffled, p, kTolerance);
    ASSERT_EQ(a.status, StencilStatus::kOk);
    EXPECT_EIGEN_NEAR(interpolate_correction(a, corrections),
                      interpolate_correction(b, corrections_shuffled), 1e-16);
  }
}

}  // namespace
}  // namespace vrreg
