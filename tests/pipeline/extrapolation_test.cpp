// SPDX-License-Identifier: Apache-2.0
// A field model never answers "ok" outside its support: far targets are flagged and left
// uncorrected, as the paper's stencils leave targets outside their grid. Asked to extrapolate,
// it corrects them with an sd that covers the error it then makes (TRE / sd of order 1), on a
// cell whose field a model fitted inside cannot know outside.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "vrreg/vrreg.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

/// The sensor's distortion at a robot position [m]: (0.15 sin(x/60), 0.12 cos(y/45),
/// 0.10 sin(z/50)) mm with x, y, z in mm.
Eigen::Vector3d distortion_m(const Eigen::Vector3d& y_m) {
  const Eigen::Vector3d y_mm = 1e3 * y_m;
  return 1e-3 * Eigen::Vector3d(0.15 * std::sin(y_mm.x() / 60.0), 0.12 * std::cos(y_mm.y() / 45.0),
                                0.10 * std::sin(y_mm.z() / 50.0));
}

/// 64 fiducials on a 4 x 4 x 4 lattice at 20 mm from (400, -100, 300) mm, read by a sensor
/// offset by (-1000, 300, 0) mm with the distortion above and 0.02 mm noise; targets one inside
/// and three outside: 1 m along x, 1 m below, 10 m along x.
struct Cube {
  MeasuredPoints fiducials, targets;
  Cube() {
    Random rng(5);
    const Eigen::Vector3d offset_m(-1.0, 0.3, 0.0);
    const auto read = [&](const Eigen::Vector3d& y_m) {
      return Eigen::Vector3d(y_m + offset_m + distortion_m(y_m) + rng.normal3(2e-5));
    };
    fiducials.robot_m.resize(3, 64);
    fiducials.sensor_m.resize(3, 64);
    for (int i = 0; i < 64; ++i) {
      fiducials.robot_m.col(i) =
          Eigen::Vector3d(0.4, -0.1, 0.3) + 0.02 * Eigen::Vector3d(i % 4, i / 4 % 4, i / 16);
      fiducials.sensor_m.col(i) = read(fiducials.robot_m.col(i));
    }
    targets.robot_m.resize(3, 4);
    targets.robot_m << 0.41, 1.46, 0.43, 10.4,  //
        -0.09, -0.1, -0.07, -0.1,               //
        0.31, 0.3, -0.7, 0.3;
    targets.sensor_m.resize(3, 4);
    for (int t = 0; t < 4; ++t) targets.sensor_m.col(t) = read(targets.robot_m.col(t));
    targets.names = {"IN", "FAR1", "BELOW", "FAR10"};
  }
};

class Extrapolation : public ::testing::TestWithParam<InterpolationMethod> {};

TEST_P(Extrapolation, FarTargetsAreFlaggedOrCorrectedWithAnSdThatCoversTheError) {
  if (testing::sanitized() && GetParam() == InterpolationMethod::kKriging) GTEST_SKIP();
  const Cube cube;
  const RegisterResult r = register_fiducials(cube.fiducials);
  EvaluateOptions options;
  options.interpolation.method = GetParam();
  const EvaluateResult flagged = evaluate(r.model, cube.targets, options);
  EXPECT_EQ(flagged.correction.stencils[0].status, StencilStatus::kOk);
  EXPECT_EQ(flagged.correction.n_flagged, 3);
  for (int t = 1; t < 4; ++t) {
    EXPECT_EQ(flagged.correction.stencils[static_cast<std::size_t>(t)].status,
              StencilStatus::kOutsideSupport);
    EXPECT_EQ(flagged.cor_tre_m(t), flagged.unc_tre_m(t)) << "uncorrected";
  }

  options.extrapolate = true;
  const EvaluateResult far = evaluate(r.model, cube.targets, options);
  EXPECT_EQ(far.correction.n_flagged, 0);
  EXPECT_EQ(far.cor_tre_m(0), flagged.cor_tre_m(0)) << "inside: the same answer";
  double sum_z2 = 0.0;
  for (int t = 1; t < 4; ++t) {
    EXPECT_EQ(far.correction.stencils[static_cast<std::size_t>(t)].status,
              StencilStatus::kExtrapolated);
    const double sd_m = far.correction.predicted_sd_m(t);
    ASSERT_TRUE(std::isfinite(sd_m) && sd_m > far.correction.predicted_sd_m(0)) << t;
    const double z = far.cor_tre_m(t) / sd_m;
    std::printf("%s: TRE %.3f -> %.3f mm, sd %.3f mm, z %.2f\n", cube.targets.names[t].c_str(),
                far.unc_tre_m(t) * 1e3, far.cor_tre_m(t) * 1e3, sd_m * 1e3, z);
    // The answer leaves the uncorrected one by no more than its sd says: never a model's runaway.
    EXPECT_LT(far.cor_tre_m(t), far.unc_tre_m(t) + 2.0 * sd_m) << t;
    sum_z2 += z * z;
  }
  const double rms_z = std::sqrt(sum_z2 / 3.0);
  EXPECT_GT(rms_z, 0.5);
  EXPECT_LT(rms_z, 1.5);
}

// The summary is over the corrected targets only: the three far targets, left uncorrected, are
// counted apart with their own RMS_T and never enter RMS_T, gamma or N_bad. Extrapolated targets
// were corrected and count.
TEST(EvaluateSummary, NeverMixesCorrectedAndUncorrectedTargets) {
  const Cube cube;
  const RegisterResult r = register_fiducials(cube.fiducials);
  EvaluateOptions options;
  options.interpolation.method = InterpolationMethod::kRbf;
  const EvaluateResult e = evaluate(r.model, cube.targets, options);
  ASSERT_EQ(e.correction.n_flagged, 3);
  EXPECT_EQ(e.n_targets(), 4);
  EXPECT_EQ(e.summary.n_targets, 1);
  EXPECT_EQ(e.summary.unc_rms_t_m, e.unc_tre_m(0));
  EXPECT_EQ(e.summary.cor_rms_t_m, e.cor_tre_m(0));
  EXPECT_EQ(e.summary.cor_max_tre_m, e.cor_tre_m(0));
  EXPECT_DOUBLE_EQ(e.summary.gamma, 1.0 - e.cor_tre_m(0) / e.unc_tre_m(0));
  const Eigen::Vector3d far = e.unc_tre_m.tail(3);
  EXPECT_DOUBLE_EQ(e.flagged_rms_t_m, std::sqrt(far.squaredNorm() / 3.0));
  for (const int k : e.summary.bad_targets) EXPECT_EQ(k, 0);

  options.extrapolate = true;
  const EvaluateResult x = evaluate(r.model, cube.targets, options);
  EXPECT_EQ(x.summary.n_targets, 4);
  EXPECT_EQ(x.flagged_rms_t_m, 0.0);
  EXPECT_DOUBLE_EQ(x.summary.cor_rms_t_m, std::sqrt(x.cor_tre_m.squaredNorm() / 4.0));
}

INSTANTIATE_TEST_SUITE_P(FieldModels, Extrapolation,
                         ::testing::Values(InterpolationMethod::kKriging,
                                           InterpolationMethod::kRbf),
                         [](const ::testing::TestParamInfo<InterpolationMethod>& p) {
                           return std::string(to_string(p.param));
                         });

}  // namespace
}  // namespace vrreg
