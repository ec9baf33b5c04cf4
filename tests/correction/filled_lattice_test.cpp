// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/filled_lattice.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "correction_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/correction/grid.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::a1_layout;
using testing::grid_points;
using testing::kTolerance;
using testing::random_affine_field;

// Trilinear interpolation reproduces affine fields, and the affine fill of a hole is exact for
// them: on A1's 25 mm lattice (a hole at every target) the corrections at the targets and at
// random points inside are the field's own values.
TEST(FilledLattice, AffineFieldIsReproducedEverywhereOnA1) {
  Random rng(3);
  const auto layout = a1_layout();
  const auto field = random_affine_field(rng);
  const FilledLattice lattice =
      fill_lattice(layout.fiducials_robot_m, field.at(layout.fiducials_robot_m), kTolerance);
  EXPECT_EQ(lattice.grid.nodes, (std::array<int, 3>{11, 13, 9}));
  EXPECT_EQ(lattice.n_fiducial_nodes, 1167);
  EXPECT_EQ(lattice.n_filled, 120);
  EXPECT_EQ(lattice.n_empty, 0);
  for (Eigen::Index t = 0; t < layout.targets_robot_m.cols(); ++t) {
    const auto c = lattice_correction(lattice, layout.targets_robot_m.col(t), kTolerance);
    ASSERT_TRUE(c);
    EXPECT_LT((*c - field(layout.targets_robot_m.col(t))).norm(), 1e-15);
  }
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d p(rng.uniform(0.3, 0.55), rng.uniform(-0.1, 0.2), rng.uniform(0.05, 0.25));
    const auto c = lattice_correction(lattice, p, kTolerance);
    ASSERT_TRUE(c);
    EXPECT_LT((*c - field(p)).norm(), 1e-15);
  }
  EXPECT_FALSE(lattice_correction(lattice, Eigen::Vector3d(0.2, 0.0, 0.1), kTolerance));
  EXPECT_NE(lattice.describe().find("120 empty nodes filled"), std::string::npos);
}

// Without holes it is the complete grid's trilinear interpolation, to the last bit.
TEST(FilledLattice, CompleteLatticeEqualsGridInterpolation) {
  Random rng(5);
  const Points3 nodes = grid_points(5, 4, 3, Eigen::Vector3d(0.03, 0.02, 0.04));
  Points3 corrections(3, nodes.cols());
  for (Eigen::Index j = 0; j < nodes.cols(); ++j) corrections.col(j) = rng.normal3(1e-4);
  const FilledLattice lattice = fill_lattice(nodes, corrections, kTolerance);
  const auto grid = detect_grid(nodes, kTolerance).grid;
  ASSERT_TRUE(grid);
  EXPECT_EQ(lattice.n_filled, 0);
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector3d p(rng.uniform(0.0, 0.12), rng.uniform(0.0, 0.06), rng.uniform(0.0, 0.08));
    const auto c = lattice_correction(lattice, p, kTolerance);
    ASSERT_TRUE(c);
    const Eigen::Vector3d expected =
        interpolate_correction(grid_stencil(*grid, p, kTolerance), corrections);
    EXPECT_EQ(*c, expected);
  }
}

// A corner node without a fiducial has too few neighbours to fill honestly: it stays empty and
// the cell that needs it gives no correction.
TEST(FilledLattice, CornerHoleStaysEmpty) {
  const Points3 all = grid_points(4, 4, 4, Eigen::Vector3d::Constant(0.025));
  Points3 nodes = all.rightCols(all.cols() - 1);  // drop node (0, 0, 0)
  // and its three face neighbours: the corner's 3 x 3 x 3 block keeps 4 fiducials (< 6)
  std::vector<Eigen::Index> keep;
  for (Eigen::Index j = 0; j < nodes.cols(); ++j) {
    const Eigen::Vector3d p = nodes.col(j) / 0.025;
    const double sum = p.sum();
    if (sum < 1.5 && (p.array() < 1.5).all()) continue;  // (1,0,0), (0,1,0), (0,0,1)
    keep.push_back(j);
  }
  Points3 kept(3, static_cast<Eigen::Index>(keep.size()));
  for (std::size_t i = 0; i < keep.size(); ++i) kept.col(static_cast<Eigen::Index>(i)) = nodes.col(keep[i]);
  const FilledLattice lattice = fill_lattice(kept, Points3::Zero(3, kept.cols()), kTolerance);
  EXPECT_EQ(lattice.n_empty, 1);
  EXPECT_EQ(lattice.n_filled, 3);
  EXPECT_FALSE(lattice_correction(lattice, Eigen::Vector3d(0.01, 0.01, 0.01), kTolerance));
  EXPECT_TRUE(lattice_correction(lattice, Eigen::Vector3d(0.06, 0.06, 0.06), kTolerance));
  EXPECT_NE(lattice.describe().find("1 left empty"), std::string::npos);
}

TEST(FilledLattice, ScatteredOrBadInputIsRefused) {
  Random rng(9);
  Points3 scattered(3, 40);
  for (Eigen::Index j = 0; j < scattered.cols(); ++j)
    scattered.col(j) = Eigen::Vector3d(rng.uniform(), rng.uniform(), rng.uniform());
  EXPECT_THAT([&] { (void)fill_lattice(scattered, Points3::Zero(3, 40), kTolerance); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("needs fiducials on a lattice")));
  const Points3 nodes = grid_points(3, 3, 3, Eigen::Vector3d::Constant(0.025));
  EXPECT_THAT([&] { (void)fill_lattice(nodes, Points3::Zero(3, 26), kTolerance); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("got 26 corrections for 27 fiducials")));
  Points3 bad = Points3::Zero(3, 27);
  bad(1, 4) = std::nan("");
  EXPECT_THAT([&] { (void)fill_lattice(nodes, bad, kTolerance); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("finite")));
  // Two far clusters: a lattice of many nodes per fiducial.
  Points3 far = grid_points(2, 2, 2, Eigen::Vector3d::Constant(0.001));
  Points3 two(3, 16);
  two << far, (far.array() + 1.0).matrix();
  EXPECT_THAT([&] { (void)fill_lattice(two, Points3::Zero(3, 16), kTolerance); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("use kriging or scattered")));
}

}  // namespace
}  // namespace vrreg
