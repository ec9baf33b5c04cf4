// SPDX-License-Identifier: Apache-2.0
#include "vrreg/registration/robust.hpp"

#include <gtest/gtest.h>

#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::random_points;
using testing::random_transform;

TEST(RegisterRigidRobust, FindsSwappedMarkers) {
  Random rng(21);
  const Points3 x = random_points(rng, 40, 0.15);
  const RigidTransform truth = random_transform(rng, 1.0);
  Points3 y = truth.apply_all(x);
  for (Eigen::Index j = 0; j < y.cols(); ++j) y.col(j) += rng.normal3(0.1e-3);
  y.col(7).swap(y.col(22));  // two markers swapped in the robot list
  const RobustRegistrationResult r = register_rigid_robust(x, y);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.rejected, (std::vector<Eigen::Index>{7, 22}));
  EXPECT_EIGEN_NEAR(r.registration.T_robot_sensor.rotation, truth.rotation, 5e-3);
  EXPECT_LT(r.registration.fre_m, 0.3e-3);
  // The plain fit is pulled by the swap.
  EXPECT_GT(register_rigid(x, y).fre_m, 10 * r.registration.fre_m);
}

TEST(RegisterRigidRobust, KeepsEveryPointOfCleanGaussianData) {
  Random rng(22);
  const Points3 x = random_points(rng, 200, 0.15);
  Points3 y = random_transform(rng, 1.0).apply_all(x);
  for (Eigen::Index j = 0; j < y.cols(); ++j) y.col(j) += rng.normal3(0.1e-3);
  const RobustRegistrationResult r = register_rigid_robust(x, y);
  ASSERT_TRUE(r.converged);
  EXPECT_TRUE(r.rejected.empty());
  EXPECT_NEAR(r.sigma_m, 0.1e-3, 0.02e-3);
}

TEST(RegisterRigidRobust, NoiseFreeWithOneGrossOutlier) {
  Random rng(23);
  const Points3 x = random_points(rng, 10, 0.1);
  const RigidTransform truth = random_transform(rng, 1.0);
  Points3 y = truth.apply_all(x);
  y.col(0) += Eigen::Vector3d(0.0, 0.02, 0.0);
  const RobustRegistrationResult r = register_rigid_robust(x, y);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.rejected, std::vector<Eigen::Index>{0});
  EXPECT_EIGEN_NEAR(r.registration.T_robot_sensor.rotation, truth.rotation, 1e-12);
  EXPECT_NEAR(r.registration.residuals_m[0], 0.02, 1e-12);
}

TEST(RegisterRigidRobust, ReportsUnusableData) {
  Random rng(24);
  const Points3 x = random_points(rng, 10, 0.1);
  const Points3 y = random_points(rng, 10, 0.1);  // no relation at all
  const RobustRegistrationResult r = register_rigid_robust(x, y);
  if (r.converged) {
    // Random data may yield a set; it must then hold at least half the points.
    EXPECT_LE(r.rejected.size(), 5u);
  } else {
    EXPECT_FALSE(r.message.empty());
  }
}

}  // namespace
}  // namespace vrreg
