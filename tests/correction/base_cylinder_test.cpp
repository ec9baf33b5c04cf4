// SPDX-License-Identifier: Apache-2.0
// The base-axis cylindrical coordinates kriging works in (correction/base_cylinder.hpp): exact on
// points whose cylindrical coordinates are known, lossless for vectors, and refused where the
// azimuth is ill-defined or would be cut.
#include "correction/base_cylinder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using detail::BaseCylinder;

Eigen::Vector3d at(double radius_m, double azimuth_rad, double z_m) {
  return {radius_m * std::cos(azimuth_rad), radius_m * std::sin(azimuth_rad), z_m};
}

TEST(BaseCylinder, CoordinatesAreRadiusArcAndHeight) {
  // Symmetric about +x: mean azimuth 0, mean radius 0.5 m.
  Points3 p(3, 3);
  p << at(0.4, 0.2, 0.1), at(0.6, -0.2, 0.3), at(0.5, 0.0, 0.2);
  const auto cylinder = BaseCylinder::fit(p);
  ASSERT_TRUE(cylinder);
  EXPECT_NEAR(cylinder->mean_radius_m(), 0.5, 1e-15);
  const Points3 c = cylinder->coordinates(p);
  EXPECT_NEAR(c(0, 0), 0.4, 1e-15);
  EXPECT_NEAR(c(1, 0), 0.5 * 0.2, 1e-15);
  EXPECT_NEAR(c(2, 0), 0.1, 1e-15);
  EXPECT_NEAR(c(1, 1), -0.5 * 0.2, 1e-15);
  EXPECT_NEAR(c(1, 2), 0.0, 1e-15);
}

// Behind the robot the fiducials straddle azimuth +-180 degrees; their coordinates must not
// jump there.
TEST(BaseCylinder, NoCutInsideTheFiducials) {
  const double pi = std::numbers::pi;
  Points3 p(3, 3);
  p << at(0.5, pi - 0.1, 0.0), at(0.5, -pi + 0.1, 0.0), at(0.5, pi, 0.0);
  const auto cylinder = BaseCylinder::fit(p);
  ASSERT_TRUE(cylinder);
  const Points3 c = cylinder->coordinates(p);
  EXPECT_NEAR(std::abs(c(1, 0) - c(1, 1)), 0.5 * 0.2, 1e-12);
  EXPECT_NEAR(c(1, 2), 0.0, 1e-12);
}

TEST(BaseCylinder, VectorsRoundTripAndRadialIsFirst) {
  Random rng(3);
  Points3 p(3, 50);
  Points3 v(3, 50);
  for (Eigen::Index j = 0; j < 50; ++j) {
    p.col(j) = at(0.3 + 0.4 * rng.uniform(), rng.uniform() - 0.5, rng.uniform());
    v.col(j) = rng.normal3(1.0);
  }
  const auto cylinder = BaseCylinder::fit(p);
  ASSERT_TRUE(cylinder);
  const Points3 local = cylinder->to_local(p, v);
  EXPECT_LT((cylinder->from_local(p, local) - v).cwiseAbs().maxCoeff(), 1e-15);
  for (Eigen::Index j = 0; j < 50; ++j) {
    EXPECT_NEAR(local.col(j).norm(), v.col(j).norm(), 1e-14);
    const Eigen::Vector3d radial(p(0, j), p(1, j), 0.0);
    EXPECT_NEAR(local(0, j), v.col(j).dot(radial.normalized()), 1e-14);
    EXPECT_NEAR(local(2, j), v(2, j), 0.0);
  }
}

TEST(BaseCylinder, RefusedNearTheAxisOrAllAround) {
  Points3 near_axis(3, 2);
  near_axis << at(0.5, 0.0, 0.0), at(0.05, 0.1, 0.0);
  EXPECT_FALSE(BaseCylinder::fit(near_axis));
  Points3 around(3, 8);  // 45 degrees apart: no empty sector of 60 degrees for the cut
  for (Eigen::Index j = 0; j < 8; ++j) around.col(j) = at(0.5, 0.25 * std::numbers::pi * static_cast<double>(j), 0.0);
  EXPECT_FALSE(BaseCylinder::fit(around));
  // Three quarters of a ring: the cut goes in the empty quarter, the reference opposite it.
  Points3 three_quarters(3, 4);
  three_quarters << at(0.5, 0.0, 0.0), at(0.5, 0.5 * std::numbers::pi, 0.0),
      at(0.5, std::numbers::pi, 0.0), at(0.5, 1.25 * std::numbers::pi, 0.0);
  const auto cylinder = BaseCylinder::fit(three_quarters);
  ASSERT_TRUE(cylinder);
  const Points3 c = cylinder->coordinates(three_quarters);
  EXPECT_NEAR(c(1, 0), -0.5 * 0.625 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(c(1, 3), 0.5 * 0.625 * std::numbers::pi, 1e-12);
  EXPECT_FALSE(BaseCylinder::fit(Points3(3, 0)));
  // A cell in front of the robot, as the project's test grids are, is accepted.
  EXPECT_TRUE(BaseCylinder::fit(testing::cube_grid_m(4, 0.025)));
}

}  // namespace
}  // namespace vrreg
