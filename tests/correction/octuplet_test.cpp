// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/octuplet.hpp"

#include <gtest/gtest.h>

#include "correction_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::kTolerance;

/// Dataset B in miniature: 8 targets, each with octuplets of edge 10, 30 and 50 mm.
struct BLayout {
  Points3 targets_m;
  Points3 fiducials_m;
};
BLayout b_layout() {
  BLayout out{testing::grid_points(2, 2, 2, Eigen::Vector3d::Constant(0.05),
                                   Eigen::Vector3d(0.4, 0.0, 0.2)),
              Points3(3, 8 * 3 * 8)};
  Eigen::Index c = 0;
  for (Eigen::Index t = 0; t < 8; ++t) {
    for (const double a : {0.010, 0.030, 0.050}) {
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1,
                                   (corner & 4) ? 1 : -1);
        out.fiducials_m.col(c++) = out.targets_m.col(t) + 0.5 * a * sign;
      }
    }
  }
  // The 50 mm cubes of neighbouring targets share corners: keep each corner once.
  std::vector<Eigen::Index> keep;
  for (Eigen::Index j = 0; j < out.fiducials_m.cols(); ++j) {
    bool seen = false;
    for (const Eigen::Index k : keep)
      seen = seen || (out.fiducials_m.col(k) - out.fiducials_m.col(j)).norm() < 1e-9;
    if (!seen) keep.push_back(j);
  }
  Points3 unique(3, static_cast<Eigen::Index>(keep.size()));
  for (std::size_t j = 0; j < keep.size(); ++j)
    unique.col(static_cast<Eigen::Index>(j)) = out.fiducials_m.col(keep[j]);
  out.fiducials_m = unique;
  return out;
}

TEST(OctupletStencils, FindsTheCubeCornersWithEqualWeights) {
  const BLayout b = b_layout();
  for (const double a : {0.010, 0.030, 0.050}) {
    const OctupletStencils stencils(b.fiducials_m, a, kTolerance);
    for (Eigen::Index t = 0; t < b.targets_m.cols(); ++t) {
      const Stencil s = stencils.stencil(b.targets_m.col(t));
      ASSERT_EQ(s.status, StencilStatus::kOk);
      ASSERT_EQ(s.size, 8);
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (std::size_t k = 0; k < 8; ++k) {
        EXPECT_EQ(s.weight[k], 0.125);
        const Eigen::Vector3d d = b.fiducials_m.col(s.fiducial[k]) - b.targets_m.col(t);
        const Eigen::Vector3d expected((k & 1U) ? 0.5 * a : -0.5 * a, (k & 2U) ? 0.5 * a : -0.5 * a,
                                       (k & 4U) ? 0.5 * a : -0.5 * a);
        EXPECT_EIGEN_NEAR(d, expected, 1e-12);
        centre += s.weight[k] * b.fiducials_m.col(s.fiducial[k]);
      }
      EXPECT_EIGEN_NEAR(centre, b.targets_m.col(t), 1e-15);
    }
  }
}

TEST(OctupletStencils, MatchesCornersWithinToleranceAndFlagsMissingOnes) {
  const BLayout b = b_layout();
  Points3 jittered = b.fiducials_m;
  Random rng(41);
  for (Eigen::Index j = 0; j < jittered.cols(); ++j)
    jittered.col(j) += rng.uniform(-0.5, 0.5) * kTolerance * Eigen::Vector3d::Ones();
  const OctupletStencils ok(jittered, 0.03, kTolerance);
  EXPECT_EQ(ok.stencil(b.targets_m.col(3)).status, StencilStatus::kOk);

  // Drop one corner of target 0's 10 mm cube (the first fiducial column).
  const Points3 missing = b.fiducials_m.rightCols(b.fiducials_m.cols() - 1);
  const OctupletStencils stencils(missing, 0.010, kTolerance);
  EXPECT_EQ(stencils.stencil(b.targets_m.col(0)).status, StencilStatus::kMissingCorner);
  EXPECT_EQ(stencils.stencil(b.targets_m.col(1)).status, StencilStatus::kOk);
  EXPECT_EQ(stencils.stencil(b.targets_m.col(0) + Eigen::Vector3d(0.004, 0, 0)).status,
            StencilStatus::kMissingCorner);
  EXPECT_EQ(stencils.describe(), "octuplet, cube edge 10 mm");
}

TEST(OctupletStencils, RejectsUnusableSettings) {
  const BLayout b = b_layout();
  EXPECT_THROW(OctupletStencils(b.fiducials_m, 0.0, kTolerance), InputError);
  EXPECT_THROW(OctupletStencils(b.fiducials_m, 0.01, 0.0), InputError);
  EXPECT_THROW(OctupletStencils(b.fiducials_m.leftCols(7), 0.01, kTolerance), InputError);
  Points3 twice(3, 2 * b.fiducials_m.cols());
  twice << b.fiducials_m, b.fiducials_m;
  EXPECT_THROW(OctupletStencils(twice, 0.01, kTolerance), InputError);
}

}  // namespace
}  // namespace vrreg
