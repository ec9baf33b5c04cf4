// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/random.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "vrreg/core/check.hpp"

#include "vrreg_test.hpp"

namespace vrreg {
namespace {

TEST(Random, SameSeedSameSequence) {
  Random a(42);
  Random b(42);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(a.normal(), b.normal());
}

TEST(Random, NormalMomentsMatchStandardNormal) {
  Random rng(7);
  const int n = 200000;
  double sum = 0.0;
  double sum_sq = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.normal();
    sum += x;
    sum_sq += x * x;
  }
  const double mean = sum / n;
  const double var = sum_sq / n - mean * mean;
  // Standard errors: 1/sqrt(n) for the mean, sqrt(2/n) for the variance; 5 sigma bands.
  EXPECT_NEAR(mean, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(var, 1.0, 5.0 * std::sqrt(2.0 / n));
}

TEST(Random, RotationIsProper) {
  Random rng(3);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Matrix3d r = rng.rotation();
    EXPECT_EIGEN_NEAR(r * r.transpose(), Eigen::Matrix3d::Identity(), 1e-14);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
  }
}

TEST(Random, BelowStaysInRange) {
  Random rng(5);
  for (int i = 0; i < 10000; ++i) EXPECT_LT(rng.below(7), 7u);
}

TEST(RigidTransform, InverseCompositionAndIsometry) {
  Random rng(11);
  const RigidTransform t = testing::random_transform(rng, 2.0);
  const Eigen::Vector3d p(0.1, -0.2, 0.3);
  EXPECT_EIGEN_NEAR(t.inverse().apply(t.apply(p)), p, 1e-15);
  const RigidTransform u = testing::random_transform(rng, 1.0);
  EXPECT_EIGEN_NEAR((t * u).apply(p), t.apply(u.apply(p)), 1e-14);
  // The same map as an Eigen isometry, and back; (R, tau) construct it.
  EXPECT_EIGEN_NEAR(t.isometry() * p, t.apply(p), 1e-15);
  const RigidTransform back(t.isometry());
  EXPECT_EIGEN_NEAR(back.rotation, t.rotation, 0.0);
  EXPECT_EIGEN_NEAR(back.translation_m, t.translation_m, 0.0);
  const RigidTransform from_parts(t.rotation, t.translation_m);
  EXPECT_EIGEN_NEAR(from_parts.apply(p), t.apply(p), 0.0);
}

TEST(SimilarityTransform, InverseCompositionAndRigidPart) {
  Random rng(13);
  const SimilarityTransform t(testing::random_transform(rng, 2.0), 1.3);
  const Eigen::Vector3d p(0.1, -0.2, 0.3);
  EXPECT_EIGEN_NEAR(t.inverse().apply(t.apply(p)), p, 1e-15);
  EXPECT_EIGEN_NEAR(t.apply(p), 1.3 * (t.rotation * p) + t.translation_m, 1e-15);
  const SimilarityTransform u = testing::random_transform(rng, 1.0);
  EXPECT_EIGEN_NEAR((t * u).apply(p), t.apply(u.apply(p)), 1e-14);
  EXPECT_THROW((void)t.rigid(), InputError);  // a similarity is not a rigid transform
  EXPECT_EIGEN_NEAR(u.rigid().apply(p), u.apply(p), 0.0);
}

}  // namespace
}  // namespace vrreg
