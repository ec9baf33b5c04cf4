// SPDX-License-Identifier: Apache-2.0
// On a synthetic smooth + wavy robot error, RRBC's corrected RMS_T falls as the fiducial grid
// spacing falls (paper section 5.1, Fig. 7), and RRBC beats the plain registration.
#include <gtest/gtest.h>

#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/registration/rigid.hpp"
#include "vrreg/simulation/cartesian_error_field.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

struct Outcome {
  double unc_rms_t_m;
  double cor_rms_t_m;
};

// Fiducials on a grid of `spacing_m` over a 200 mm cube; targets at fixed random positions.
Outcome run(double spacing_m, const CartesianErrorField& field, const RigidTransform& T_sensor_robot,
            const Points3& targets_robot, Random& noise) {
  const int n = static_cast<int>(std::lround(0.2 / spacing_m)) + 1;
  Points3 fid_robot(3, n * n * n);
  int c = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) fid_robot.col(c++) = spacing_m * Eigen::Vector3d(i, j, k);
  auto measure = [&](const Points3& nominal) {
    Points3 sensor(3, nominal.cols());
    for (Eigen::Index q = 0; q < nominal.cols(); ++q) {
      sensor.col(q) = T_sensor_robot.apply(Eigen::Vector3d(nominal.col(q)) +
                                           field.error_m(nominal.col(q))) +
                      noise.normal3(0.02e-3);
    }
    return sensor;
  };
  const Points3 fid_sensor = measure(fid_robot);
  CorrectionField model;
  model.T_robot_sensor = register_rigid(fid_sensor, fid_robot).T_robot_sensor;
  model.corrections_sensor_m = fiducial_corrections(model.T_robot_sensor, fid_sensor, fid_robot);
  model.fiducials_robot_m = fid_robot;
  InterpolationSettings settings;
  settings.method = InterpolationMethod::kGrid;
  const Points3 targets_sensor = measure(targets_robot);
  const TargetCorrection tc = correct_targets(model, targets_sensor, targets_robot, settings);
  EXPECT_EQ(tc.n_flagged, 0);
  return {root_mean_square(point_errors(tc.uncorrected_robot_m, targets_robot)),
          root_mean_square(point_errors(tc.corrected_robot_m, targets_robot))};
}

TEST(GridSpacing, CorrectedErrorFallsAsSpacingFalls) {
  Random rng(61);
  const Eigen::Vector3d centre(0.1, 0.1, 0.1);
  const CartesianErrorField field = CartesianErrorField::random(rng, centre, 0.1, 0.6e-3, 0.15e-3);
  RigidTransform T_sensor_robot = testing::random_transform(rng, 2.0);
  const Points3 targets = testing::random_points(rng, 200, 0.095, centre);
  std::vector<double> cor;
  for (double spacing : {0.1, 0.05, 0.025, 0.0125}) {
    Random noise(62);
    const Outcome o = run(spacing, field, T_sensor_robot, targets, noise);
    EXPECT_LT(o.cor_rms_t_m, o.unc_rms_t_m) << "spacing " << spacing;
    cor.push_back(o.cor_rms_t_m);
  }
  for (std::size_t k = 1; k < cor.size(); ++k) {
    EXPECT_LT(cor[k], cor[k - 1]) << "spacing step " << k;
  }
  // At 12.5 mm the wavy field (wavelengths >= 60 mm) is resolved: the corrected error nears the
  // noise floor, sqrt(3) * 0.02 mm on the target plus at most as much from the interpolated
  // fiducial noise (sum w^2 <= 1).
  const double noise_floor_m = std::sqrt(3.0) * 0.02e-3 * std::sqrt(2.0);
  EXPECT_LT(cor.back(), 1.5 * noise_floor_m);
  EXPECT_LT(cor.back(), 0.25 * cor.front());
}

}  // namespace
}  // namespace vrreg
