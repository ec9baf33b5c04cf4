// SPDX-License-Identifier: Apache-2.0
#include <cmath>

#include <gtest/gtest.h>

#include "vrreg/core/check.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/improvement.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

TEST(Errors, TreAndRmsByHand) {
  RigidTransform t;
  t.translation_m = Eigen::Vector3d(1.0, 0.0, 0.0);
  Points3 sensor(3, 2), robot(3, 2);
  sensor << 0, 1, 0, 0, 0, 0;
  robot << 1.003, 2.0, 0.004, 0.0, 0.0, 0.0;
  const Eigen::VectorXd tre = target_registration_errors(t, sensor, robot);
  EXPECT_NEAR(tre[0], 0.005, 1e-15);
  EXPECT_NEAR(tre[1], 0.0, 1e-15);
  EXPECT_NEAR(root_mean_square(tre), std::sqrt(0.005 * 0.005 / 2), 1e-16);
  EXPECT_EQ(root_mean_square(Eigen::VectorXd()), 0.0);
}

TEST(Noise, SigmaOptAveragesPerAxisVariances) {
  // Two locations: readings {0, 2} on x only (variance 2 on x, 0 on y, z -> per-axis mean 2/3)
  // and K=3 readings {1, 2, 3} on every axis (variance 1 per axis).
  Location a;
  a.n_readings = 2;
  a.sensor_sq_dev_m2 = Eigen::Vector3d(2.0, 0.0, 0.0);
  Location b;
  b.n_readings = 3;
  b.sensor_sq_dev_m2 = Eigen::Vector3d(2.0, 2.0, 2.0);
  Location single;
  single.n_readings = 1;
  const auto s = sigma_opt_m({a, b, single});
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(*s, std::sqrt((2.0 / 3.0 + 1.0) / 2.0), 1e-15);
  EXPECT_FALSE(sigma_opt_m({single}).has_value());
}

TEST(Noise, SigmaNoiseAndRhoReproducePaperTable1) {
  // Table 1, A1: sigma_opt 0.058 mm, sigma_rep 0.1 mm -> sigma_noise 0.1156 -> 0.114 printed from
  // unrounded inputs; rho = 0.626 / 0.114 = 5.5.
  EXPECT_NEAR(sigma_noise_m(0.058e-3, 0.1e-3), 0.1156e-3, 0.0005e-3);
  EXPECT_NEAR(rho(0.626e-3, 0.114e-3), 5.49, 0.01);
  EXPECT_THROW(rho(1.0, 0.0), InputError);
  EXPECT_THROW(sigma_noise_m(-1.0, 0.0), InputError);
}

TEST(Improvement, GammaNBadAndDeltaTre) {
  Eigen::VectorXd unc(4), cor(4);
  unc << 1.0, 2.0, 0.5, 1.0;
  cor << 0.5, 1.0, 0.7, 1.0;
  const ImprovementSummary s = summarize_improvement(unc, cor);
  EXPECT_EQ(s.n_targets, 4);
  EXPECT_NEAR(s.unc_rms_t_m, std::sqrt((1 + 4 + 0.25 + 1) / 4.0), 1e-15);
  EXPECT_NEAR(s.cor_rms_t_m, std::sqrt((0.25 + 1 + 0.49 + 1) / 4.0), 1e-15);
  EXPECT_NEAR(s.gamma, (s.unc_rms_t_m - s.cor_rms_t_m) / s.unc_rms_t_m, 1e-15);
  EXPECT_EQ(s.n_bad, 1);
  EXPECT_EQ(s.bad_targets, std::vector<int>{2});
  ASSERT_EQ(s.delta_tre_m.size(), 2);
  EXPECT_DOUBLE_EQ(s.delta_tre_m[0], -0.5);
  EXPECT_DOUBLE_EQ(s.delta_tre_m[1], -1.0);
  EXPECT_THROW(summarize_improvement(unc, cor.head(3)), InputError);
}

}  // namespace
}  // namespace vrreg
