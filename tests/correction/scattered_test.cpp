// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/scattered.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <set>

#include "correction_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/correction/delaunay.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::a1_layout;
using testing::grid_points;
using testing::permuted;
using testing::random_affine_field;
using testing::random_permutation;
using testing::random_points;

using testing::kTolerance;

/// A random point inside the convex hull: a random convex combination of four fiducials.
Eigen::Vector3d random_inside(Random& rng, const Points3& fiducials) {
  Eigen::Vector4d w(rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform());
  w /= w.sum();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    p += w(k) * fiducials.col(static_cast<Eigen::Index>(
                    rng.below(static_cast<std::uint64_t>(fiducials.cols()))));
  }
  return p;
}

double tet_volume(const Points3& p, const std::array<Eigen::Index, 4>& v) {
  Eigen::Matrix3d e;
  for (int c = 0; c < 3; ++c) e.col(c) = p.col(v[static_cast<std::size_t>(c) + 1]) - p.col(v[0]);
  return std::abs(e.determinant()) / 6.0;
}

TEST(Delaunay, TilesTheHullWithSymmetricNeighbours) {
  for (const Points3& points :
       {grid_points(5, 4, 3, Eigen::Vector3d(0.025, 0.02, 0.03), Eigen::Vector3d(0.4, 0.1, 0.2)),
        a1_layout().fiducials_robot_m}) {
    const Tetrahedralization mesh = delaunay_tetrahedralization(points);
    const Eigen::Vector3d extent = points.rowwise().maxCoeff() - points.rowwise().minCoeff();
    double volume = 0.0;
    std::set<Eigen::Index> used;
    for (std::size_t t = 0; t < mesh.vertices.size(); ++t) {
      volume += tet_volume(points, mesh.vertices[t]);
      used.insert(mesh.vertices[t].begin(), mesh.vertices[t].end());
      for (std::size_t k = 0; k < 4; ++k) {
        const Eigen::Index n = mesh.neighbours[t][k];
        if (n < 0) continue;
        const auto& back = mesh.neighbours[static_cast<std::size_t>(n)];
        EXPECT_NE(std::find(back.begin(), back.end(), static_cast<Eigen::Index>(t)), back.end());
      }
    }
    EXPECT_NEAR(volume, extent.prod(), 1e-12 * extent.prod());  // the hull is the box
    EXPECT_EQ(static_cast<Eigen::Index>(used.size()), points.cols());
  }
}

TEST(ScatteredStencils, ReproducesAffineFieldsInsideTheHull) {
  Random rng(17);
  const Points3 fiducials = random_points(rng, 400, 0.15, Eigen::Vector3d(0.5, 0.0, 0.3));
  const ScatteredStencils stencils(fiducials, kTolerance);
  const auto field = random_affine_field(rng);
  const Points3 corrections = field.at(fiducials);
  for (int trial = 0; trial < 5000; ++trial) {
    const Eigen::Vector3d p = random_inside(rng, fiducials);
    const Stencil s = stencils.stencil(p);
    ASSERT_EQ(s.status, StencilStatus::kOk);
    ASSERT_EQ(s.size, 4);
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(s.weight[static_cast<std::size_t>(k)], 0.0);
      EXPECT_LE(s.weight[static_cast<std::size_t>(k)], 1.0);
      sum += s.weight[static_cast<std::size_t>(k)];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_EIGEN_NEAR(interpolate_correction(s, corrections), field(p), 1e-15);
  }
}

TEST(ScatteredStencils, ExactAtFiducials) {
  Random rng(19);
  for (const Points3& fiducials : {random_points(rng, 300, 0.1), a1_layout().fiducials_robot_m}) {
    const ScatteredStencils stencils(fiducials, kTolerance);
    Points3 corrections = random_affine_field(rng).at(fiducials);
    corrections += 1e-4 * (50.0 * corrections.array()).sin().matrix();  // not affine
    for (Eigen::Index j = 0; j < fiducials.cols(); ++j) {
      const Stencil s = stencils.stencil(fiducials.col(j));
      ASSERT_EQ(s.status, StencilStatus::kOk);
      EXPECT_EIGEN_NEAR(interpolate_correction(s, corrections), corrections.col(j), 1e-15);
    }
  }
}

TEST(ScatteredStencils, FlagsPointsOutsideTheHull) {
  const Points3 box = grid_points(3, 3, 3, Eigen::Vector3d::Constant(0.05));
  const ScatteredStencils stencils(box, kTolerance);
  EXPECT_EQ(stencils.stencil(Eigen::Vector3d(0.05, 0.05, 0.1 + 1e-4)).status,
            StencilStatus::kOutsideHull);
  EXPECT_EQ(stencils.stencil(Eigen::Vector3d(-1.0, 2.0, 0.05)).status, StencilStatus::kOutsideHull);
  EXPECT_EQ(stencils.stencil(Eigen::Vector3d(0.11, 0.11, 0.11)).status,
            StencilStatus::kOutsideHull);
  // On the hull, or within the tolerance outside it: inside.
  EXPECT_EQ(stencils.stencil(Eigen::Vector3d(0.031, 0.017, 0.1)).status, StencilStatus::kOk);
  EXPECT_EQ(stencils.stencil(Eigen::Vector3d(0.031, 0.017, 0.1 + 0.5 * kTolerance)).status,
            StencilStatus::kOk);
  // A corner cut off: the hull of a tetrahedron-shaped layout excludes the box corner.
  Random rng(23);
  const Points3 ball = random_points(rng, 300, 0.1);
  const ScatteredStencils sparse(ball, kTolerance);
  int outside = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const Eigen::Vector3d far = random_points(rng, 1, 0.1).col(0).normalized() * 0.2;
    outside += sparse.stencil(far).status == StencilStatus::kOutsideHull ? 1 : 0;
  }
  EXPECT_EQ(outside, 1000);
}

TEST(ScatteredStencils, GridLayoutsWithFlatTetrahedra) {
  Random rng(29);
  const auto a1 = a1_layout();
  const ScatteredStencils stencils(a1.fiducials_robot_m, kTolerance);
  EXPECT_GT(stencils.n_flat(), 0);
  const auto field = random_affine_field(rng);
  const Points3 corrections = field.at(a1.fiducials_robot_m);
  int fallbacks = 0;
  const int trials = testing::sanitized() ? 2000 : 20000;
  for (int trial = 0; trial < trials; ++trial) {
    const Eigen::Vector3d p =
        Eigen::Vector3d(0.3, -0.1, 0.05) +
        Eigen::Vector3d(rng.uniform(0, 0.25), rng.uniform(0, 0.3), rng.uniform(0, 0.2));
    LocateStats stats;
    const Stencil s = stencils.stencil(p, &stats);
    ASSERT_EQ(s.status, StencilStatus::kOk);
    EXPECT_EIGEN_NEAR(interpolate_correction(s, corrections), field(p), 1e-15);
    fallbacks += stats.fallback ? 1 : 0;
  }
  EXPECT_LE(fallbacks, trials / 1000) << "the walk should rarely give up";
  for (Eigen::Index t = 0; t < a1.targets_robot_m.cols(); ++t) {
    EXPECT_EQ(stencils.stencil(a1.targets_robot_m.col(t)).status, StencilStatus::kOk);
  }
}

TEST(ScatteredStencils, ConcentricCubesAndHullBoundary) {
  // Dataset B's pattern: octuplets of 10 edges (5..50 mm) around targets on a 50 mm grid: many
  // cospherical points, many flat tetrahedra. The hull is the box of the 50 mm cube corners.
  std::vector<Eigen::Vector3d> points;
  const Points3 targets = grid_points(3, 3, 2, Eigen::Vector3d::Constant(0.05));
  for (Eigen::Index t = 0; t < targets.cols(); ++t) {
    for (int e = 1; e <= 10; ++e) {
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1,
                                   (corner & 4) ? 1 : -1);
        const Eigen::Vector3d p = targets.col(t) + 0.0025 * e * sign;
        bool seen = false;
        for (const auto& q : points) seen = seen || (q - p).norm() < 1e-9;
        if (!seen) points.push_back(p);
      }
    }
  }
  Points3 fiducials(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t j = 0; j < points.size(); ++j)
    fiducials.col(static_cast<Eigen::Index>(j)) = points[j];
  const ScatteredStencils stencils(fiducials, kTolerance);
  EXPECT_GT(stencils.n_flat(), 0);
  Random rng(43);
  const auto field = random_affine_field(rng);
  const Points3 corrections = field.at(fiducials);
  const Eigen::Vector3d lo(-0.025, -0.025, -0.025);
  const Eigen::Vector3d hi(0.125, 0.125, 0.075);
  int fallbacks = 0;
  const int trials = testing::sanitized() ? 2000 : 20000;
  for (int trial = 0; trial < trials; ++trial) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a) p(a) = rng.uniform(lo(a), hi(a));
    const int axis = trial % 4;  // 3 of 4 points on (or just off) a face of the hull box
    if (axis < 3) p(axis) = (trial % 8 < 4 ? lo(axis) : hi(axis)) + rng.uniform(-2, 2) * kTolerance;
    const bool outside = ((p - hi).maxCoeff() > kTolerance) || ((lo - p).maxCoeff() > kTolerance);
    LocateStats stats;
    const Stencil s = stencils.stencil(p, &stats);
    fallbacks += stats.fallback ? 1 : 0;
    if (outside) {
      EXPECT_EQ(s.status, StencilStatus::kOutsideHull) << p.transpose();
    } else if ((p - hi).maxCoeff() <= 0.0 && (lo - p).maxCoeff() <= 0.0) {
      ASSERT_EQ(s.status, StencilStatus::kOk) << p.transpose();
      EXPECT_EIGEN_NEAR(interpolate_correction(s, corrections), field(p), 1e-15);
    }
  }
  EXPECT_LE(fallbacks, trials / 1000);
}

TEST(ScatteredStencils, InvariantToFiducialOrder) {
  Random rng(31);
  const Points3 fiducials = random_points(rng, 300, 0.1);
  const auto order = random_permutation(rng, fiducials.cols());
  const ScatteredStencils a(fiducials, kTolerance);
  const ScatteredStencils b(permuted(fiducials, order), kTolerance);
  Points3 corrections = random_affine_field(rng).at(fiducials);
  corrections += 1e-4 * (50.0 * corrections.array()).sin().matrix();
  const Points3 corrections_b = permuted(corrections, order);
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d p = random_inside(rng, fiducials);
    const Stencil sa = a.stencil(p);
    const Stencil sb = b.stencil(p);
    ASSERT_EQ(sa.status, StencilStatus::kOk);
    ASSERT_EQ(sb.status, StencilStatus::kOk);
    EXPECT_EIGEN_NEAR(interpolate_correction(sa, corrections),
                      interpolate_correction(sb, corrections_b), 1e-15);
  }
}

TEST(ScatteredStencils, RejectsUnusableLayouts) {
  Random rng(37);
  EXPECT_THROW(ScatteredStencils(random_points(rng, 3, 0.1), kTolerance), InputError);
  EXPECT_THROW(ScatteredStencils(grid_points(5, 5, 1, Eigen::Vector3d::Constant(0.02)), kTolerance),
               InputError);
  Points3 line(3, 10);
  for (int j = 0; j < 10; ++j) line.col(j) = Eigen::Vector3d(1, 2, 3) * 0.01 * j;
  EXPECT_THROW(ScatteredStencils(line, kTolerance), InputError);
  Points3 twice(3, 40);
  const Points3 some = random_points(rng, 20, 0.1);
  twice << some, some;
  try {
    ScatteredStencils s(twice, kTolerance);
    ADD_FAILURE() << "duplicates accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("share a nominal robot position"), std::string::npos)
        << e.what();
  }
  Points3 nan = random_points(rng, 10, 0.1);
  nan(2, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ScatteredStencils(nan, kTolerance), InputError);
}

}  // namespace
}  // namespace vrreg
