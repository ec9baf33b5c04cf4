// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/rrbc.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::random_points;
using testing::random_transform;

TEST(FiducialCorrections, MatchesHandComputation) {
  // R: 90 degrees about z, tau = (1, 2, 3) m. R' Y - R' tau for Y = (1.5, 2.25, 2.9):
  // Y - tau = (0.5, 0.25, -0.1); R' (x, y, z) = (y, -x, z) -> (0.25, -0.5, -0.1).
  RigidTransform T;
  T.rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  T.translation_m = Eigen::Vector3d(1, 2, 3);
  Points3 x(3, 2);
  Points3 y(3, 2);
  x.col(0) << 0.2501, -0.4998, -0.1003;
  y.col(0) << 1.5, 2.25, 2.9;
  x.col(1) << 0.0, 0.0, 0.0;
  y.col(1) << 1.0, 2.0, 3.0;  // maps exactly onto tau: correction zero
  Points3 expected(3, 2);
  expected.col(0) << 0.25 - 0.2501, -0.5 + 0.4998, -0.1 + 0.1003;
  expected.col(1).setZero();
  EXPECT_EIGEN_NEAR(fiducial_corrections(T, x, y), expected, 1e-15);
}

TEST(FiducialCorrections, WithScaleDividesByIt) {
  SimilarityTransform T;
  T.scale = 2.0;
  T.translation_m = Eigen::Vector3d(0.1, 0.0, 0.0);
  Points3 x = Points3::Zero(3, 1);
  Points3 y(3, 1);
  y << 0.5, 0.2, -0.4;  // (y - t) / 2 = (0.2, 0.1, -0.2)
  EXPECT_EIGEN_NEAR(fiducial_corrections(T, x, y), Eigen::Vector3d(0.2, 0.1, -0.2), 1e-16);
}

TEST(FiducialCorrections, CorrectedFiducialsMapExactlyOntoRobotPositions) {
  Random rng(20240601);
  for (const double scale : {1.0, 0.999}) {
    for (int trial = 0; trial < 20; ++trial) {
      const SimilarityTransform T(random_transform(rng, 2.0), scale);
      const Points3 x = random_points(rng, 50, 0.3, Eigen::Vector3d(0.1, 2.0, -0.5));
      const Points3 y = random_points(rng, 50, 0.3, Eigen::Vector3d(0.4, 0.0, 0.2));
      const Points3 eps = fiducial_corrections(T, x, y);
      for (Eigen::Index j = 0; j < x.cols(); ++j) {
        // Eq. 5 and 6: R (X + eps) + tau = Y.
        EXPECT_EIGEN_NEAR(T.apply(Eigen::Vector3d(x.col(j) + eps.col(j))), y.col(j), 1e-12);
      }
    }
  }
}

TEST(FiducialCorrections, RejectsBadInput) {
  const RigidTransform T;
  const Points3 three = Points3::Zero(3, 3);
  const Points3 two = Points3::Zero(3, 2);
  EXPECT_THROW((void)fiducial_corrections(T, three, two), InputError);
  Points3 nan = three;
  nan(1, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)fiducial_corrections(T, nan, three), InputError);
  RigidTransform bad;
  bad.translation_m.x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW((void)fiducial_corrections(bad, three, three), InputError);
}

TEST(Interpolation, WeightedSumOfCorrections) {
  Points3 eps(3, 3);
  eps << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  Stencil s;
  s.size = 2;
  s.fiducial[0] = 2;
  s.fiducial[1] = 0;
  s.weight[0] = 0.25;
  s.weight[1] = 0.75;
  EXPECT_EIGEN_NEAR(interpolate_correction(s, eps), Eigen::Vector3d(1.5, 4.5, 7.5), 1e-15);
  EXPECT_STREQ(to_string(StencilStatus::kOutsideHull), "outside hull");
  EXPECT_STREQ(to_string(StencilStatus::kOk), "ok");
}

}  // namespace
}  // namespace vrreg
