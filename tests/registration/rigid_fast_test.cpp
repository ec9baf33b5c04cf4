// SPDX-License-Identifier: Apache-2.0
// register_rigid without residuals (RegistrationOptions::residuals = false): the transform from
// the compensated one-pass moments and FRE in closed form, against the residuals path and a
// two-pass FRE in extended precision.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "registration/rigid_moments.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/registration/rigid.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::random_points;
using testing::random_transform;

struct Case {
  Points3 x, y;
};

// J points in a box of half-size half_m around `centre`, mapped by a random motion, plus noise.
Case make_case(Random& rng, int n, double half_m, const Eigen::Vector3d& centre, double noise_m,
               double max_translation_m = 1.5) {
  Case c;
  c.x = random_points(rng, n, half_m, centre);
  const RigidTransform truth = random_transform(rng, max_translation_m);
  c.y = truth.apply_all(c.x);
  for (Eigen::Index j = 0; j < n; ++j) c.y.col(j) += rng.normal3(noise_m);
  return c;
}

// sum w |s R x + tau - y|^2 / sum w for the given transform, in extended precision.
double two_pass_fre(const Case& c, const SimilarityTransform& t, const Eigen::VectorXd& w = {}) {
  long double sum = 0.0L, wsum = 0.0L;
  for (Eigen::Index j = 0; j < c.x.cols(); ++j) {
    long double r2 = 0.0L;
    for (int i = 0; i < 3; ++i) {
      long double v = static_cast<long double>(t.translation_m[i]) - c.y(i, j);
      for (int k = 0; k < 3; ++k) {
        v += static_cast<long double>(t.scale) * t.rotation(i, k) * c.x(k, j);
      }
      r2 += v * v;
    }
    const long double wj = w.size() != 0 ? w[j] : 1.0;
    sum += wj * r2;
    wsum += wj;
  }
  return static_cast<double>(std::sqrt(sum / wsum));
}

// The closed form subtracts numbers of the size of the spread terms (sum |a - a_mean|^2 +
// sum |b - b_mean|^2) to get FRE^2: its relative error is about 1e-16 times their ratio to FRE^2
// (2e-12 for 0.5 mm noise on a 0.3 m layout), never better than 1e-12 is asked.
double closed_form_tolerance(const Case& c, double fre_m) {
  const double n = static_cast<double>(c.x.cols());
  const double spread_sq = ((c.x.colwise() - c.x.rowwise().mean()).squaredNorm() +
                            (c.y.colwise() - c.y.rowwise().mean()).squaredNorm()) /
                           n;
  return std::max(1e-12, 2e-16 * spread_sq / (fre_m * fre_m)) * fre_m;
}

RegistrationOptions fast_options() {
  RegistrationOptions o;
  o.residuals = false;
  return o;
}

void expect_same_transform(const RegistrationResult& fast, const RegistrationResult& full) {
  EXPECT_EIGEN_NEAR(fast.T_robot_sensor.rotation, full.T_robot_sensor.rotation, 1e-13);
  const double t_scale = 1.0 + full.T_robot_sensor.translation_m.norm();
  EXPECT_EIGEN_NEAR(fast.T_robot_sensor.translation_m, full.T_robot_sensor.translation_m,
                    1e-13 * t_scale);
  EXPECT_NEAR(fast.T_robot_sensor.scale, full.T_robot_sensor.scale, 1e-13);
  // Squared spreads are the singular values: absolute agreement relative to the largest.
  EXPECT_EIGEN_NEAR(fast.spread_m.cwiseAbs2(), full.spread_m.cwiseAbs2(),
                    1e-13 * full.spread_m[0] * full.spread_m[0]);
  EXPECT_NEAR(fast.collinearity, full.collinearity, 1e-12);
}

// Typical data (mm noise on a 0.3 m layout), near the origin and far from it, at the sizes of
// the paper's data sets and beyond: closed-form FRE = two-pass FRE (see closed_form_tolerance). Far
// from the origin no FRE is better than the rounding of the coordinates themselves (each residual
// R x + tau - y is formed from numbers of size |offset|), hence the absolute floor.
TEST(RegisterRigidFast, ClosedFormFreMatchesTwoPass) {
  Random rng(11);
  for (const int n : {3, 8, 63, 64, 65, 519, 1000, 9600, 100000}) {
    for (const double offset_m : {0.0, 2.0, 1e3, 1e5}) {
      for (const double noise_m : {0.5e-3, 1e-5}) {
        SCOPED_TRACE(::testing::Message()
                     << "n " << n << " offset " << offset_m << " noise " << noise_m);
        const Case c = make_case(rng, n, 0.15, Eigen::Vector3d(offset_m, -0.5 * offset_m, 0.3),
                                 noise_m, 1.5 + offset_m);
        const RegistrationResult fast = register_rigid(c.x, c.y, fast_options());
        const RegistrationResult full = register_rigid(c.x, c.y);
        EXPECT_EQ(fast.residuals_m.size(), 0);
        expect_same_transform(fast, full);
        const double reference = two_pass_fre(c, fast.T_robot_sensor);
        const double floor = 1e-15 * (1.0 + offset_m);
        EXPECT_NEAR(fast.fre_m, reference, closed_form_tolerance(c, reference) + floor);
        EXPECT_NEAR(full.fre_m, reference, 1e-12 * reference + floor);
      }
    }
  }
}

// Near-perfect fits (FRE ~ 1e-9 of the spread, or exact): the closed form would lose every digit,
// so the residual pass takes over and FRE still matches.
TEST(RegisterRigidFast, NearPerfectFitFallsBackToResiduals) {
  Random rng(12);
  for (const double noise_m : {1e-10, 1e-13, 0.0}) {
    const Case c = make_case(rng, 5000, 0.15, Eigen::Vector3d(100.0, 3.0, -20.0), noise_m, 50.0);
    const RegistrationResult fast = register_rigid(c.x, c.y, fast_options());
    const RegistrationResult full = register_rigid(c.x, c.y);
    expect_same_transform(fast, full);
    const double reference = two_pass_fre(c, fast.T_robot_sensor);
    EXPECT_NEAR(fast.fre_m, reference, 1e-12 * reference + 1e-15 * 100.0);
  }
}

TEST(RegisterRigidFast, WeightsAndScale) {
  Random rng(13);
  Case c = make_case(rng, 3000, 0.2, Eigen::Vector3d(1.0, 2.0, 3.0), 0.3e-3);
  c.y *= 1.001;  // a scale for estimate_scale to find
  Eigen::VectorXd w(c.x.cols());
  for (Eigen::Index j = 0; j < w.size(); ++j) w[j] = rng.uniform(0.0, 2.0);
  w[5] = 0.0;
  for (const bool scale : {false, true}) {
    RegistrationOptions fast = fast_options();
    fast.estimate_scale = scale;
    RegistrationOptions full;
    full.estimate_scale = scale;
    const RegistrationResult a = register_rigid(c.x, c.y, fast, w);
    const RegistrationResult b = register_rigid(c.x, c.y, full, w);
    expect_same_transform(a, b);
    const double reference = two_pass_fre(c, a.T_robot_sensor, w);
    EXPECT_NEAR(a.fre_m, reference, closed_form_tolerance(c, reference));
    EXPECT_NEAR(b.fre_m, reference, 1e-12 * reference);
  }
}

// Strided input (a block of a larger matrix) takes the general loads: same result.
TEST(RegisterRigidFast, StridedInputGivesTheSameResult) {
  Random rng(14);
  const Case c = make_case(rng, 777, 0.1, Eigen::Vector3d(0.5, 0.2, 1.0), 1e-4);
  Eigen::MatrixXd big_x = Eigen::MatrixXd::Zero(5, 777), big_y = Eigen::MatrixXd::Zero(5, 777);
  big_x.topRows(3) = c.x;
  big_y.topRows(3) = c.y;
  const Eigen::Map<const Eigen::Matrix3Xd, 0, Eigen::OuterStride<>> sx(big_x.data(), 3, 777,
                                                                       Eigen::OuterStride<>(5));
  const Eigen::Map<const Eigen::Matrix3Xd, 0, Eigen::OuterStride<>> sy(big_y.data(), 3, 777,
                                                                       Eigen::OuterStride<>(5));
  const RegistrationResult a = register_rigid(c.x, c.y, fast_options());
  const RegistrationResult b = register_rigid(sx, sy, fast_options());
  EXPECT_EQ(a.T_robot_sensor.rotation, b.T_robot_sensor.rotation);
  EXPECT_EQ(a.T_robot_sensor.translation_m, b.T_robot_sensor.translation_m);
  EXPECT_EQ(a.fre_m, b.fre_m);
}

// Every kernel this CPU has (AVX-512VL, AVX2 + FMA) gives the portable kernel's bits, so results
// do not depend on the machine.
TEST(RegisterRigidFast, KernelsAgreeBitForBit) {
  Random rng(15);
  for (const int n : {1, 3, 4, 5, 63, 64, 65, 130, 1001}) {
    const Case c = make_case(rng, n, 0.2, Eigen::Vector3d(3.0, 1.0, -2.0), 1e-3);
    Eigen::VectorXd w(n);
    for (Eigen::Index j = 0; j < n; ++j) w[j] = rng.uniform(0.1, 3.0);
    const Eigen::Vector3d sx = c.x.col(0), sy = c.y.col(0);
    for (const bool weighted : {false, true}) {
      const Eigen::VectorXd& ww = weighted ? w : Eigen::VectorXd();
      detail::FastMoments b;
      ASSERT_TRUE(
          detail::fast_moments_using(detail::MomentKernel::kPortable, c.x, c.y, ww, sx, sy, b));
      const detail::FastMoments dispatched = detail::fast_moments(c.x, c.y, ww, sx, sy);
      for (const auto kernel : {detail::MomentKernel::kAvx2, detail::MomentKernel::kAvx512}) {
        detail::FastMoments a = dispatched;
        if (!detail::fast_moments_using(kernel, c.x, c.y, ww, sx, sy, a)) continue;
        for (int k = 0; k < detail::kMoments; ++k) {
          EXPECT_EQ(a.hi[k], b.hi[k]) << "n " << n << " k " << k;
          EXPECT_EQ(a.lo[k], b.lo[k]) << "n " << n << " k " << k;
          EXPECT_EQ(dispatched.hi[k], b.hi[k]) << "n " << n << " k " << k;
        }
      }
    }
  }
}

TEST(RegisterRigidFast, RejectsTheSameBadInput) {
  Random rng(16);
  Points3 line(3, 10);
  for (int j = 0; j < 10; ++j) line.col(j) = Eigen::Vector3d(j, 2.0 * j, -j);
  EXPECT_THROW(register_rigid(line, line, fast_options()), InputError);
  Points3 x = random_points(rng, 10, 0.1), y = x;
  x(1, 4) = std::nan("");
  EXPECT_THROW(register_rigid(x, y, fast_options()), InputError);
  EXPECT_THROW(register_rigid(x.leftCols(2), y.leftCols(2), fast_options()), InputError);
  // The same past 64 points, where the one-pass kernel runs.
  Points3 long_line(3, 200);
  for (int j = 0; j < 200; ++j) long_line.col(j) = Eigen::Vector3d(j, 2.0 * j, -j);
  EXPECT_THROW(register_rigid(long_line, long_line, fast_options()), InputError);
  Points3 u = random_points(rng, 200, 0.1), v = u;
  v(2, 150) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(register_rigid(u, v, fast_options()), InputError);
  Points3 huge = u * 1e300;
  EXPECT_THROW(register_rigid(huge, huge, fast_options()), InputError);
}

}  // namespace
}  // namespace vrreg
