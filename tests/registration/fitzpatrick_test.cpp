// SPDX-License-Identifier: Apache-2.0
// Monte Carlo against Fitzpatrick, West and Maurer (1998): <TRE^2> and <FRE^2>, within 3 %.
#include "vrreg/registration/fitzpatrick.hpp"

#include <gtest/gtest.h>

#include "vrreg/registration/rigid.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

TEST(Fitzpatrick, MonteCarloMatchesTreAndFrePrediction) {
  Random rng(31);
  // An anisotropic layout, so the three principal axes differ.
  Points3 fiducials(3, 8);
  fiducials << 0.10, -0.10, 0.08, -0.06, 0.02, -0.03, 0.09, -0.09,  //
      0.05, 0.04, -0.05, -0.04, 0.01, 0.03, -0.02, 0.00,              //
      0.02, -0.01, 0.00, 0.02, -0.03, 0.01, 0.00, -0.01;
  const std::vector<Eigen::Vector3d> targets = {
      {0.0, 0.0, 0.0}, {0.2, 0.1, 0.05}, {-0.05, 0.15, -0.1}, {0.3, -0.2, 0.2}};
  const double sigma_m = 0.1e-3;
  const double fle_sq = 3.0 * sigma_m * sigma_m;
  const int trials = testing::sanitized() ? 20000 : 60000;
  const RigidTransform truth = testing::random_transform(rng, 1.0);
  const Points3 robot = truth.apply_all(fiducials);

  std::vector<double> tre_sq_sum(targets.size(), 0.0);
  double fre_sq_sum = 0.0;
  for (int t = 0; t < trials; ++t) {
    Points3 noisy = fiducials;
    for (Eigen::Index j = 0; j < noisy.cols(); ++j) noisy.col(j) += rng.normal3(sigma_m);
    const RegistrationResult r = register_rigid(noisy, robot);
    fre_sq_sum += r.fre_m * r.fre_m;
    for (std::size_t k = 0; k < targets.size(); ++k) {
      tre_sq_sum[k] += (r.T_robot_sensor.apply(targets[k]) - truth.apply(targets[k])).squaredNorm();
    }
  }
  // Relative standard error of a mean of chi-square-like values ~ sqrt(2/3/trials) < 0.6 %.
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const double predicted = expected_tre_squared(fiducials, targets[k], fle_sq);
    EXPECT_NEAR(tre_sq_sum[k] / trials / predicted, 1.0, 0.03) << "target " << k;
  }
  EXPECT_NEAR(fre_sq_sum / trials / expected_fre_squared(8, fle_sq), 1.0, 0.03);
}

TEST(Fitzpatrick, CentroidTargetGivesFleOverN) {
  Points3 f(3, 4);
  f << 1, -1, 0, 0, 0, 0, 1, -1, 0.5, 0.5, -0.5, -0.5;
  const Eigen::Vector3d centroid = f.rowwise().mean();
  EXPECT_DOUBLE_EQ(expected_tre_squared(f, centroid, 3.0), 3.0 / 4.0);
}

}  // namespace
}  // namespace vrreg
