// SPDX-License-Identifier: Apache-2.0
#include "vrreg/registration/rigid.hpp"

#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::random_points;
using testing::random_transform;

// Noise-free: the transform comes back to 1e-12 relative.
TEST(RegisterRigid, RecoversKnownTransformExactly) {
  Random rng(1);
  for (int trial = 0; trial < 50; ++trial) {
    const Points3 x = random_points(rng, 3 + trial, 0.15, Eigen::Vector3d(2.0, -0.3, 1.1));
    const RigidTransform truth = random_transform(rng, 1.5);
    const Points3 y = truth.apply_all(x);
    const RegistrationResult r = register_rigid(x, y);
    EXPECT_EIGEN_NEAR(r.T_robot_sensor.rotation, truth.rotation, 1e-12);
    EXPECT_EIGEN_NEAR(r.T_robot_sensor.translation_m, truth.translation_m, 1e-12 * 2.0);
    EXPECT_EQ(r.T_robot_sensor.scale, 1.0);
    EXPECT_LT(r.fre_m, 1e-13);
    EXPECT_NEAR(r.T_robot_sensor.rotation.determinant(), 1.0, 1e-14);
  }
}

// The SVD alone would return a reflection for mirrored data; we must not.
TEST(RegisterRigid, NeverReturnsAReflection) {
  Random rng(2);
  const Points3 x = random_points(rng, 20, 0.1);
  Points3 y = x;
  y.row(2) *= -1.0;  // mirror image: the best orthogonal map is a reflection
  const RegistrationResult r = register_rigid(x, y);
  EXPECT_NEAR(r.T_robot_sensor.rotation.determinant(), 1.0, 1e-12);
  EXPECT_EIGEN_NEAR(r.T_robot_sensor.rotation * r.T_robot_sensor.rotation.transpose(),
                    Eigen::Matrix3d::Identity(), 1e-12);
}

// Reference: the rotation from the quaternion (Horn 1987) method, an independent closed form.
Eigen::Matrix3d horn_rotation(const Points3& x, const Points3& y) {
  const Points3 a = x.colwise() - x.rowwise().mean();
  const Points3 b = y.colwise() - y.rowwise().mean();
  const Eigen::Matrix3d m = a * b.transpose();
  Eigen::Matrix4d n;
  n << m(0, 0) + m(1, 1) + m(2, 2), m(1, 2) - m(2, 1), m(2, 0) - m(0, 2), m(0, 1) - m(1, 0),
      m(1, 2) - m(2, 1), m(0, 0) - m(1, 1) - m(2, 2), m(0, 1) + m(1, 0), m(2, 0) + m(0, 2),
      m(2, 0) - m(0, 2), m(0, 1) + m(1, 0), -m(0, 0) + m(1, 1) - m(2, 2), m(1, 2) + m(2, 1),
      m(0, 1) - m(1, 0), m(2, 0) + m(0, 2), m(1, 2) + m(2, 1), -m(0, 0) - m(1, 1) + m(2, 2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(n);
  const Eigen::Vector4d q = eig.eigenvectors().col(3);
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
}

TEST(RegisterRigid, NoisyDataMatchesHornQuaternionMethod) {
  Random rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const Points3 x = random_points(rng, 50, 0.12, Eigen::Vector3d(1.0, 2.0, 0.5));
    Points3 y = random_transform(rng, 2.0).apply_all(x);
    for (Eigen::Index j = 0; j < y.cols(); ++j) y.col(j) += rng.normal3(0.5e-3);
    const RegistrationResult r = register_rigid(x, y);
    EXPECT_EIGEN_NEAR(r.T_robot_sensor.rotation, horn_rotation(x, y), 1e-10);
  }
}

TEST(RegisterRigid, InvariantToRigidMotionOfEitherSetAndToPointOrder) {
  Random rng(4);
  const Points3 x = random_points(rng, 30, 0.1);
  Points3 y = random_transform(rng, 1.0).apply_all(x);
  for (Eigen::Index j = 0; j < y.cols(); ++j) y.col(j) += rng.normal3(1e-3);
  const RegistrationResult base = register_rigid(x, y);

  const RigidTransform move_robot = random_transform(rng, 3.0);
  const RegistrationResult moved_y = register_rigid(x, move_robot.apply_all(y));
  EXPECT_NEAR(moved_y.fre_m, base.fre_m, 1e-13);
  EXPECT_EIGEN_NEAR((move_robot * base.T_robot_sensor).rotation, moved_y.T_robot_sensor.rotation,
                    1e-11);
  EXPECT_EIGEN_NEAR(moved_y.residuals_m, base.residuals_m, 1e-13);

  const RigidTransform move_sensor = random_transform(rng, 3.0);
  const RegistrationResult moved_x = register_rigid(move_sensor.apply_all(x), y);
  EXPECT_NEAR(moved_x.fre_m, base.fre_m, 1e-13);
  EXPECT_EIGEN_NEAR((moved_x.T_robot_sensor * move_sensor).rotation, base.T_robot_sensor.rotation,
                    1e-11);

  std::vector<Eigen::Index> order(static_cast<std::size_t>(x.cols()));
  std::iota(order.begin(), order.end(), 0);
  std::reverse(order.begin(), order.end());
  std::swap(order[3], order[17]);
  Points3 xp(3, x.cols()), yp(3, x.cols());
  for (std::size_t k = 0; k < order.size(); ++k) {
    xp.col(static_cast<Eigen::Index>(k)) = x.col(order[k]);
    yp.col(static_cast<Eigen::Index>(k)) = y.col(order[k]);
  }
  const RegistrationResult permuted = register_rigid(xp, yp);
  EXPECT_EIGEN_NEAR(permuted.T_robot_sensor.rotation, base.T_robot_sensor.rotation, 1e-13);
  EXPECT_NEAR(permuted.fre_m, base.fre_m, 1e-15);
}

TEST(RegisterRigid, IntegerWeightsEqualRepeatedPoints) {
  Random rng(5);
  const Points3 x = random_points(rng, 12, 0.1);
  Points3 y = random_transform(rng, 1.0).apply_all(x);
  for (Eigen::Index j = 0; j < y.cols(); ++j) y.col(j) += rng.normal3(2e-3);
  Eigen::VectorXd w(12);
  w << 1, 2, 3, 1, 1, 4, 2, 1, 1, 3, 1, 2;
  Points3 xr(3, static_cast<Eigen::Index>(w.sum())), yr(3, xr.cols());
  Eigen::Index k = 0;
  for (Eigen::Index j = 0; j < 12; ++j) {
    for (int rep = 0; rep < static_cast<int>(w[j]); ++rep, ++k) {
      xr.col(k) = x.col(j);
      yr.col(k) = y.col(j);
    }
  }
  const RegistrationResult weighted = register_rigid(x, y, {}, w);
  const RegistrationResult repeated = register_rigid(xr, yr);
  EXPECT_EIGEN_NEAR(weighted.T_robot_sensor.rotation, repeated.T_robot_sensor.rotation, 1e-12);
  EXPECT_EIGEN_NEAR(weighted.T_robot_sensor.translation_m, repeated.T_robot_sensor.translation_m,
                    1e-12);
  EXPECT_NEAR(weighted.fre_m, repeated.fre_m, 1e-14);
}

TEST(RegisterRigid, ZeroWeightIgnoresAPoint) {
  Random rng(6);
  const Points3 x = random_points(rng, 10, 0.1);
  const RigidTransform truth = random_transform(rng, 1.0);
  Points3 y = truth.apply_all(x);
  y.col(4) += Eigen::Vector3d(0.05, -0.02, 0.03);  // a gross outlier, given no weight
  Eigen::VectorXd w = Eigen::VectorXd::Ones(10);
  w[4] = 0.0;
  const RegistrationResult r = register_rigid(x, y, {}, w);
  EXPECT_EIGEN_NEAR(r.T_robot_sensor.rotation, truth.rotation, 1e-12);
  EXPECT_NEAR(r.residuals_m[4], 0.05 * std::sqrt(1 + 0.16 + 0.36), 1e-12);
}

TEST(RegisterRigid, RecoversUniformScaleWhenAsked) {
  Random rng(7);
  const Points3 x = random_points(rng, 25, 0.1);
  const SimilarityTransform truth(random_transform(rng, 1.0), 1.0013);
  const Points3 y = truth.apply_all(x);
  RegistrationOptions options;
  options.estimate_scale = true;
  const RegistrationResult r = register_rigid(x, y, options);
  EXPECT_NEAR(r.T_robot_sensor.scale, truth.scale, 1e-12);
  EXPECT_EIGEN_NEAR(r.T_robot_sensor.rotation, truth.rotation, 1e-12);
  EXPECT_LT(r.fre_m, 1e-13);
  // Without scale the same data leave a residual proportional to the scale error.
  EXPECT_GT(register_rigid(x, y).fre_m, 1e-5);
}

TEST(RegisterRigid, ReportsSpreadAlongPrincipalAxes) {
  Points3 x(3, 4);
  x << 0.1, -0.1, 0.0, 0.0,  //
      0.0, 0.0, 0.05, -0.05,  //
      0.0, 0.0, 0.0, 0.0;
  const RegistrationResult r = register_rigid(x, x);
  EXPECT_NEAR(r.spread_m[0], std::sqrt(0.02 / 4), 1e-15);
  EXPECT_NEAR(r.spread_m[1], std::sqrt(0.005 / 4), 1e-15);
  EXPECT_NEAR(r.spread_m[2], 0.0, 1e-9);  // closed-form eigenvalues: ~sqrt(eps) * spread
  EXPECT_NEAR(r.collinearity, 0.5, 1e-14);
}

TEST(RegisterRigid, RejectsDegenerateInput) {
  Points3 two(3, 2);
  two << 0, 1, 0, 0, 0, 0;
  EXPECT_THROW(register_rigid(two, two), InputError);

  Points3 collinear(3, 5);
  for (int j = 0; j < 5; ++j) collinear.col(j) = Eigen::Vector3d(1, 2, 3) * 0.01 * j;
  try {
    (void)register_rigid(collinear, collinear);
    FAIL() << "collinear points accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("collinear"));
  }

  Points3 coincident = Points3::Constant(3, 4, 0.3);
  try {
    (void)register_rigid(coincident, coincident);
    FAIL() << "coincident points accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("coincide"));
  }

  Random rng(8);
  Points3 x = random_points(rng, 6, 0.1);
  Points3 y = x;
  y(1, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(register_rigid(x, y), InputError);
  EXPECT_THROW(register_rigid(x, x.leftCols(5)), InputError);
  Eigen::VectorXd negative = Eigen::VectorXd::Ones(6);
  negative[2] = -1.0;
  EXPECT_THROW(register_rigid(x, x, {}, negative), InputError);
}

}  // namespace
}  // namespace vrreg
