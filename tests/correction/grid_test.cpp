// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/grid.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "correction_fixtures.hpp"
#include "vrreg/core/units.hpp"
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

/// x_mm as a CSV holding it with `decimals` digits after the point gives it back, in metres.
double written_mm(double x_mm, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, x_mm);
  return units::mm_to_m(std::strtod(text, nullptr));
}

/// n points uniform in the paper's 250 x 300 x 200 mm volume, each written with min_decimals to
/// max_decimals decimals.
Points3 random_written(Random& rng, Eigen::Index n, int min_decimals, int max_decimals) {
  Points3 out(3, n);
  const Eigen::Vector3d lo(300.0, -150.0, 50.0);
  const Eigen::Vector3d size(250.0, 300.0, 200.0);
  for (Eigen::Index j = 0; j < n; ++j) {
    const int decimals =
        min_decimals +
        static_cast<int>(rng.below(static_cast<std::uint64_t>(max_decimals - min_decimals + 1)));
    for (int a = 0; a < 3; ++a) out(a, j) = written_mm(lo(a) + size(a) * rng.uniform(), decimals);
  }
  return out;
}

/// 10^4 nodes, 25 x 20 x 20 at 10 x 12.5 x 10 mm.
Points3 ten_thousand_nodes() {
  return grid_points(25, 20, 20, Eigen::Vector3d(0.01, 0.0125, 0.01),
                     Eigen::Vector3d(0.3, -0.15, 0.05));
}

/// The columns `keep` of `points`.
Points3 columns(const Points3& points, const std::vector<Eigen::Index>& keep) {
  Points3 out(3, static_cast<Eigen::Index>(keep.size()));
  for (std::size_t j = 0; j < keep.size(); ++j)
    out.col(static_cast<Eigen::Index>(j)) = points.col(keep[j]);
  return out;
}

/// Every node of `grid` holds its fiducial, within twice the tolerance of the node's position
/// (the lattice is fitted to level means).
void expect_complete(const GridLayout& grid, const Points3& fiducials) {
  ASSERT_EQ(grid.fiducial.size(),
            static_cast<std::size_t>(grid.nodes[0]) * grid.nodes[1] * grid.nodes[2]);
  for (int k = 0; k < grid.nodes[2]; ++k) {
    for (int j = 0; j < grid.nodes[1]; ++j) {
      for (int i = 0; i < grid.nodes[0]; ++i) {
        const Eigen::Vector3d node =
            grid.origin_m + Eigen::Vector3d(i, j, k).cwiseProduct(grid.spacing_m);
        EXPECT_LE((fiducials.col(grid.node_fiducial(i, j, k)) - node).cwiseAbs().maxCoeff(),
                  2 * kTolerance);
      }
    }
  }
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

TEST(DetectGrid, RefusesRandomLayoutsWrittenWithThreeToSixDecimals) {
  // Their levels match a lattice of the last written digit or of about the tolerance (any
  // spacing under twice the tolerance matches every value): refused at once.
  const std::array<int, 2> decimals[] = {{3, 6}, {3, 3}, {4, 4}, {5, 5}, {6, 6}};
  for (const Eigen::Index n : {Eigen::Index{700}, Eigen::Index{10000}}) {
    for (const auto& [lo, hi] : decimals) {
      for (const std::uint64_t seed : {1U, 2U}) {
        Random rng(seed);
        const GridDetection d = detect_grid(random_written(rng, n, lo, hi), kTolerance);
        EXPECT_FALSE(d.grid) << n << " points with " << lo << "-" << hi << " decimals, seed "
                             << seed << ": " << d.grid->describe();
        EXPECT_FALSE(d.reason.empty());
      }
    }
  }
}

TEST(DetectGrid, RefusesALatticeHoldingFewerThanOneNodeIn1000) {
  // 700 random nodes of a 1 mm lattice: each fiducial on a node, 10^9 nodes.
  Random rng(13);
  Points3 sparse(3, 700);
  for (Eigen::Index j = 0; j < sparse.cols(); ++j) {
    sparse.col(j) = 1e-3 * Eigen::Vector3d(static_cast<double>(rng.below(1000)),
                                           static_cast<double>(rng.below(1000)),
                                           static_cast<double>(rng.below(1000)));
  }
  const GridDetection d = detect_grid(sparse, kTolerance);
  EXPECT_FALSE(d.grid);
  EXPECT_NE(d.reason.find("fewer than 1 in 1000: scattered, not a grid"), std::string::npos)
      << d.reason;

  // A complete grid with one stray fiducial 10 mm off a node. 5^3 at 100 mm: its 10 mm lattice
  // holds 126 fiducials on 41^3 nodes (1 in 547), the every-10th grid is found. 12^3 at 110 mm:
  // 1729 fiducials on 122^3 nodes (1 in 1050), refused.
  struct Case {
    int n;
    double pitch_m;
    bool found;
  };
  for (const Case& c : {Case{5, 0.1, true}, Case{12, 0.11, false}}) {
    Points3 stray(3, c.n * c.n * c.n + 1);
    stray << grid_points(c.n, c.n, c.n, Eigen::Vector3d::Constant(c.pitch_m)),
        Eigen::Vector3d::Constant(0.01);
    const GridDetection g = detect_grid(stray, kTolerance);
    if (c.found) {
      ASSERT_TRUE(g.grid) << g.reason;
      EXPECT_EQ(g.grid->stride, 10);
      EXPECT_EQ(g.grid->nodes, (std::array<int, 3>{5, 5, 5}));
      EXPECT_EIGEN_NEAR(g.grid->spacing_m, Eigen::Vector3d::Constant(0.1), 1e-12);
      expect_complete(*g.grid, stray);
    } else {
      EXPECT_FALSE(g.grid);
      EXPECT_NE(g.reason.find("the 122 x 122 x 122 lattice of 10 x 10 x 10 mm holds 1729 "
                              "fiducials on 1815848 nodes, fewer than 1 in 1000"),
                std::string::npos)
          << g.reason;
    }
  }
}

TEST(DetectGrid, DatasetBKeepsItsEveryTenthGrid) {
  // The paper's dataset B: cubes of 50, 45, ..., 5 mm edge around A1's 120 targets, each corner
  // once. Its 2.5 mm lattice holds 8850 fiducials on 101 x 121 x 81 nodes (1 in 112); the
  // corners of the 25 mm cubes make the every-10th grid.
  std::set<std::array<int, 3>> corners;  // in 2.5 mm steps
  for (int tz = 0; tz < 4; ++tz) {
    for (int ty = 0; ty < 6; ++ty) {
      for (int tx = 0; tx < 5; ++tx) {
        const std::array<int, 3> centre = {10 + 20 * tx, 10 + 20 * ty, 10 + 20 * tz};
        for (int half = 1; half <= 10; ++half) {
          for (int corner = 0; corner < 8; ++corner) {
            corners.insert({centre[0] + ((corner & 1) != 0 ? half : -half),
                            centre[1] + ((corner & 2) != 0 ? half : -half),
                            centre[2] + ((corner & 4) != 0 ? half : -half)});
          }
        }
      }
    }
  }
  Points3 b(3, static_cast<Eigen::Index>(corners.size()));
  Eigen::Index j = 0;
  for (const auto& [x, y, z] : corners) {
    b.col(j++) = Eigen::Vector3d(0.3, -0.15, 0.05) + 2.5e-3 * Eigen::Vector3d(x, y, z);
  }
  ASSERT_EQ(b.cols(), 8850);
  const GridLayout grid = detect_or_fail(b);
  EXPECT_EQ(grid.describe(),
            "grid 10 x 12 x 8 nodes, 25 x 25 x 25 mm (every 10th fiducial; 960 of 8850 fiducials)");
  expect_complete(grid, b);
}

TEST(DetectGrid, JitteredLattices) {
  const Points3 nodes = ten_thousand_nodes();
  for (const double jitter : {0.4 * kTolerance, 5 * kTolerance, 1e-3}) {
    Random rng(17);
    Points3 jittered = nodes;
    for (Eigen::Index j = 0; j < jittered.cols(); ++j) {
      for (int a = 0; a < 3; ++a) jittered(a, j) += rng.uniform(-jitter, jitter);
    }
    const GridDetection d = detect_grid(jittered, kTolerance);
    if (jitter < kTolerance) {  // small against the tolerance: the same grid
      ASSERT_TRUE(d.grid) << d.reason;
      EXPECT_EQ(d.grid->nodes, (std::array<int, 3>{25, 20, 20}));
      EXPECT_EQ(d.grid->stride, 1);
      EXPECT_EIGEN_NEAR(d.grid->spacing_m, Eigen::Vector3d(0.01, 0.0125, 0.01), kTolerance);
      for (Eigen::Index j = 0; j < nodes.cols(); ++j)
        EXPECT_EQ(d.grid->fiducial[static_cast<std::size_t>(j)], j);
    } else {
      EXPECT_FALSE(d.grid) << "jitter " << jitter << " m: " << d.grid->describe();
    }
  }
}

TEST(DetectGrid, HoledLattices) {
  // A2: 21 x 25 x 17 at 12.5 mm minus the all-odd nodes (targets): the every-2nd grid.
  {
    const Points3 full = grid_points(21, 25, 17, Eigen::Vector3d::Constant(0.0125));
    Points3 a2(3, full.cols());
    Eigen::Index c = 0;
    for (Eigen::Index n = 0; n < full.cols(); ++n) {
      const Eigen::Index i = n % 21;
      const Eigen::Index j = (n / 21) % 25;
      const Eigen::Index k = n / (21 * 25);
      if (i % 2 == 0 || j % 2 == 0 || k % 2 == 0) a2.col(c++) = full.col(n);
    }
    const Points3 fiducials = a2.leftCols(c);
    ASSERT_EQ(fiducials.cols(), 7965);
    const GridLayout grid = detect_or_fail(fiducials);
    EXPECT_EQ(grid.nodes, (std::array<int, 3>{11, 13, 9}));
    EXPECT_EQ(grid.stride, 2);
    expect_complete(grid, fiducials);
  }
  // A 6 x 7 x 5 grid at 50 mm with 20 fiducials between its nodes: the 25 mm lattice holds
  // 230 of 1287 nodes (18 %), the 50 mm grid is found.
  {
    Random rng(19);
    Points3 fiducials(3, 230);
    fiducials.leftCols(210) = grid_points(6, 7, 5, Eigen::Vector3d::Constant(0.05));
    for (Eigen::Index j = 210; j < 230; ++j) {
      fiducials.col(j) = 0.025 * Eigen::Vector3d(static_cast<double>(2 * rng.below(5) + 1),
                                                 static_cast<double>(2 * rng.below(6) + 1),
                                                 static_cast<double>(2 * rng.below(4) + 1));
    }
    // Distinct nodes: drop repeats of the same odd node.
    std::vector<Eigen::Index> keep;
    for (Eigen::Index j = 0; j < fiducials.cols(); ++j) {
      bool repeat = false;
      for (const Eigen::Index m : keep) repeat = repeat || fiducials.col(m) == fiducials.col(j);
      if (!repeat) keep.push_back(j);
    }
    const Points3 distinct = columns(fiducials, keep);
    const GridLayout grid = detect_or_fail(distinct);
    EXPECT_EQ(grid.nodes, (std::array<int, 3>{6, 7, 5}));
    EXPECT_EQ(grid.stride, 2);
    EXPECT_EIGEN_NEAR(grid.origin_m, Eigen::Vector3d::Zero(), 1e-12);
    EXPECT_EIGEN_NEAR(grid.spacing_m, Eigen::Vector3d::Constant(0.05), 1e-12);
    expect_complete(grid, distinct);
  }
  // Random holes in 10^4 nodes: never the full grid; whatever is found is complete.
  const Points3 nodes = ten_thousand_nodes();
  for (const double holes : {0.01, 0.3, 0.9, 0.99}) {
    Random rng(23);
    std::vector<Eigen::Index> keep;
    for (Eigen::Index j = 0; j < nodes.cols(); ++j) {
      if (rng.uniform() >= holes) keep.push_back(j);
    }
    const Points3 holed = columns(nodes, keep);
    const GridDetection d = detect_grid(holed, kTolerance);
    if (d.grid) {
      EXPECT_GT(d.grid->stride, 1) << holes;
      expect_complete(*d.grid, holed);
    }
  }
}

TEST(DetectGrid, RotatedLattices) {
  const Points3 nodes = ten_thousand_nodes();
  const Eigen::Vector3d centre = nodes.rowwise().mean();
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 3.0).normalized();
  // 1e-6 rad moves no node by more than 0.2 um (0.2 tolerances): the same grid.
  // 1e-4 rad moves them by up to 17 um, and a random orientation anywhere: no grid.
  Random rng(29);
  const std::pair<Eigen::Matrix3d, bool> cases[] = {
      {Eigen::AngleAxisd(1e-6, axis).toRotationMatrix(), true},
      {Eigen::AngleAxisd(1e-4, axis).toRotationMatrix(), false},
      {rng.rotation(), false},
  };
  for (const auto& [rotation, is_grid] : cases) {
    Points3 rotated = rotation * (nodes.colwise() - centre);
    rotated.colwise() += centre;
    const GridDetection d = detect_grid(rotated, kTolerance);
    if (is_grid) {
      ASSERT_TRUE(d.grid) << d.reason;
      EXPECT_EQ(d.grid->nodes, (std::array<int, 3>{25, 20, 20}));
      EXPECT_EQ(d.grid->stride, 1);
    } else {
      EXPECT_FALSE(d.grid) << d.grid->describe();
    }
  }
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
