// SPDX-License-Identifier: Apache-2.0
// Rotations against closed forms: Rodrigues' formula, exp and log inverse to rounding from 1e-9
// rad to pi, the Karcher mean of rotations balanced about one, the quaternion mean's spread.
#include "vrreg/core/rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vrreg/core/file_error.hpp"
#include "vrreg/core/random.hpp"

namespace vrreg {
namespace {

TEST(Rotation, ExpAndLogAreInverseToRounding) {
  Random rng(3);
  for (int i = 0; i < 200; ++i) {
    // From 1e-9 rad (where the trace formula loses every digit) to just below pi.
    const double angle = i < 100 ? std::pow(10.0, -9.0 + 0.09 * i) : 3.1 * rng.uniform();
    const Eigen::Vector3d w = angle * rng.normal3(1.0).normalized();
    const Eigen::Vector3d back = rotation_log(rotation_exp(w));
    EXPECT_LT((back - w).norm(), 1e-15 + 1e-13 * angle) << "angle " << angle;
    EXPECT_NEAR(rotation_angle_rad(Eigen::Matrix3d::Identity(), rotation_exp(w)), angle,
                1e-15 + 1e-13 * angle);
  }
  // Rodrigues' formula by hand for one rotation.
  const Eigen::Vector3d w(0.3, -0.2, 0.1);
  const double t = w.norm();
  Eigen::Matrix3d k;
  k << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  const Eigen::Matrix3d rodrigues =
      Eigen::Matrix3d::Identity() + std::sin(t) / t * k + (1 - std::cos(t)) / (t * t) * k * k;
  EXPECT_LT((rotation_exp(w) - rodrigues).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(Rotation, MeanOfRotationsBalancedAboutOneIsThatOne) {
  // exp(+v_j) M and exp(-v_j) M: the tangent vectors sum to zero at M, so M is the Karcher mean.
  Random rng(5);
  const Eigen::Matrix3d M = rng.rotation();
  std::vector<Eigen::Matrix3d> rotations;
  for (int j = 0; j < 20; ++j) {
    const Eigen::Vector3d v = rng.normal3(0.2);
    rotations.push_back(rotation_exp(v) * M);
    rotations.push_back(rotation_exp(-v) * M);
  }
  EXPECT_LT(rotation_angle_rad(rotation_mean(rotations), M), 1e-14);
  // Of one rotation, itself; of none, an error.
  EXPECT_LT(rotation_angle_rad(rotation_mean(std::vector<Eigen::Matrix3d>{M}), M), 1e-15);
  EXPECT_THROW(rotation_mean(std::vector<Eigen::Matrix3d>{}), InputError);
}

TEST(Rotation, QuaternionMeanAndSpreadMatchTheReadings) {
  // Readings at +-a about one axis around q0: mean q0, summed squared angles 2 n a^2.
  const Eigen::Quaterniond q0(rotation_exp(Eigen::Vector3d(0.4, -0.1, 0.9)));
  constexpr double a = 1e-3;
  Eigen::Matrix4d sum = Eigen::Matrix4d::Zero();
  for (const double s : {a, -a, a, -a}) {
    const Eigen::Quaterniond q(rotation_exp(Eigen::Vector3d(0.0, s, 0.0)) * q0.toRotationMatrix());
    sum += q.coeffs() * q.coeffs().transpose();
  }
  const QuaternionMean m = quaternion_mean(sum, 4, q0);
  EXPECT_LT(m.mean.angularDistance(q0), 1e-12);
  EXPECT_GT(m.mean.coeffs().dot(q0.coeffs()), 0.0);  // the sign of sign_of
  EXPECT_NEAR(m.sq_dev_rad2, 4 * a * a, 1e-12);
}

TEST(Rotation, KukaAbcIsZThenYThenXInDegrees) {
  // Closed forms: A turns about z, B about y, C about x; A = 90 takes x to y.
  EXPECT_LT(
      (rotation_from_kuka_abc_deg({90, 0, 0}) * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY())
          .norm(),
      1e-15);
  EXPECT_LT(
      (rotation_from_kuka_abc_deg({0, 90, 0}) * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX())
          .norm(),
      1e-15);
  EXPECT_LT(
      (rotation_from_kuka_abc_deg({0, 0, 90}) * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ())
          .norm(),
      1e-15);
  // Composition order: Rz(A) Ry(B) Rx(C), the intrinsic z, y', x'' of KUKA's FRAME.
  const Eigen::Matrix3d R = rotation_from_kuka_abc_deg({30, -20, 110});
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(-M_PI / 9, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(110 * M_PI / 180, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_LT((R - expected).cwiseAbs().maxCoeff(), 1e-15);
  const Eigen::Vector3d abc = kuka_abc_deg(R);
  EXPECT_NEAR(abc(0), 30, 1e-12);
  EXPECT_NEAR(abc(1), -20, 1e-12);
  EXPECT_NEAR(abc(2), 110, 1e-12);
}

TEST(Rotation, KukaAbcRoundTripsEveryRotationAndTheGimbalLock) {
  Random rng(5);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Matrix3d R = rng.rotation();
    const Eigen::Vector3d abc = kuka_abc_deg(R);
    EXPECT_LE(std::abs(abc(1)), 90.0);
    EXPECT_LE(std::abs(abc(0)), 180.0);
    EXPECT_LE(std::abs(abc(2)), 180.0);
    EXPECT_LT(rotation_angle_rad(rotation_from_kuka_abc_deg(abc), R), 5e-14)
        << i;  // ulps of the degree conversions
  }
  for (const double b : {90.0, -90.0}) {  // only A +- C defined: C = 0, the same rotation
    const Eigen::Matrix3d R = rotation_from_kuka_abc_deg({40, b, -25});
    const Eigen::Vector3d abc = kuka_abc_deg(R);
    EXPECT_EQ(abc(2), 0.0);
    EXPECT_LT(rotation_angle_rad(rotation_from_kuka_abc_deg(abc), R), 1e-12) << b;
  }
}

TEST(Rotation, UnitQuaternionKeepsUnitBitsNormalisesNearlyUnitAndRefusesTheRest) {
  const Eigen::Quaterniond q(rotation_exp(Eigen::Vector3d(0.3, -1.2, 0.4)));
  EXPECT_EQ(unit_quaternion(q.coeffs(), "q").coeffs(), q.coeffs());
  const Eigen::Quaterniond scaled = unit_quaternion(1.0005 * q.coeffs(), "q");
  EXPECT_NEAR(scaled.norm(), 1.0, 1e-15);
  EXPECT_LT(scaled.angularDistance(q), 1e-15);
  EXPECT_THROW((void)unit_quaternion(1.01 * q.coeffs(), "q"), InputError);
  EXPECT_THROW((void)unit_quaternion(Eigen::Vector4d(0, 0, std::nan(""), 1), "q"), InputError);
  try {
    (void)unit_quaternion(Eigen::Vector4d(1, 1, 1, 1), "row 7");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("row 7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vrreg
