// SPDX-License-Identifier: Apache-2.0
// Orientation RRBC against closed forms: a constant rotation residual removed exactly by every
// method, and a residual field linear on the tangent space at its mean reproduced exactly by
// trilinear interpolation of a grid.
#include "vrreg/correction/orientation_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "correction_fixtures.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/rotation.hpp"

namespace vrreg {
namespace {

// A grid of fiducials read by an unrotated sensor (positions exact: zero corrections), with
// commanded orientations `R_cmd` and measured ones made to give the residuals D_j.
struct OrientationCell {
  CorrectorData data;
  std::vector<Eigen::Matrix3d> measured;
  std::vector<Eigen::Matrix3d> commanded;
};

OrientationCell cell(const Points3& fiducials_m, const SimilarityTransform& T,
                     const auto& residual_of) {
  OrientationCell c;
  const Points3 sensor_m = T.rigid().inverse().apply_all(fiducials_m);
  c.data = CorrectorData::of(T, sensor_m, fiducials_m, Points3::Zero(3, fiducials_m.cols()));
  Random rng(11);
  for (Eigen::Index j = 0; j < fiducials_m.cols(); ++j) {
    c.commanded.push_back(rng.rotation());
    // D = R_cmd (R R_sm)^T  =>  R_sm = R^T D^T R_cmd.
    c.measured.push_back(T.rotation.transpose() * residual_of(fiducials_m.col(j)).transpose() *
                         c.commanded.back());
  }
  return c;
}

// The largest angle between the corrected and the commanded orientation of targets at `points_m`.
double worst_target_angle(const OrientationCorrector& field, const SimilarityTransform& T,
                          const Points3& points_m, const auto& residual_of) {
  const Points3 sensor_m = T.rigid().inverse().apply_all(points_m);
  Random rng(13);
  std::vector<Eigen::Matrix3d> commanded, measured;
  for (Eigen::Index t = 0; t < points_m.cols(); ++t) {
    commanded.push_back(rng.rotation());
    measured.push_back(T.rotation.transpose() * residual_of(points_m.col(t)).transpose() *
                       commanded.back());
  }
  const OrientationCorrection c =
      field.correct(CorrectionQuery(sensor_m, points_m, Eigen::MatrixXd(0, 0)), measured);
  EXPECT_EQ(c.n_flagged, 0);
  double worst = 0.0;
  for (std::size_t t = 0; t < commanded.size(); ++t) {
    worst = std::max(worst, rotation_angle_rad(c.corrected_R_robot_marker[t], commanded[t]));
  }
  return worst;
}

const SimilarityTransform kT(RigidTransform(rotation_exp(Eigen::Vector3d(0.3, -1.2, 0.5)),
                                            Eigen::Vector3d(0.2, 1.4, -0.3)));

TEST(OrientationField, ConstantResidualIsRemovedExactlyByEveryMethod) {
  const Eigen::Matrix3d C = rotation_exp(Eigen::Vector3d(2e-3, -1e-3, 3e-3));
  const auto constant = [&C](const Eigen::Vector3d&) { return C; };
  const Points3 fiducials = testing::grid_points(6, 6, 6, Eigen::Vector3d::Constant(0.05),
                                                 Eigen::Vector3d(0.3, -0.1, 0.1));
  const OrientationCell c = cell(fiducials, kT, constant);
  const Points3 residuals = rotation_residuals_rad(kT.rotation, c.measured, c.commanded);
  for (Eigen::Index j = 0; j < residuals.cols(); ++j)
    ASSERT_LT((residuals.col(j) - rotation_log(C)).norm(), 1e-15);
  const Points3 targets = testing::grid_points(3, 3, 3, Eigen::Vector3d::Constant(0.07),
                                               Eigen::Vector3d(0.33, -0.07, 0.13));
  for (const InterpolationMethod m : {InterpolationMethod::kLinear, InterpolationMethod::kScattered,
                                      InterpolationMethod::kTrilinear, InterpolationMethod::kRbf,
                                      InterpolationMethod::kKriging}) {
    CorrectorOptions options;
    options.interpolation.method = m;
    const Corrector positions = Corrector::fit(c.data, options);
    const OrientationCorrector field = OrientationCorrector::fit(positions, c.data, residuals);
    EXPECT_EQ(field.method(), positions.method());
    EXPECT_LT(rotation_angle_rad(field.mean_residual(), C), 1e-15) << to_string(m);
    EXPECT_LT(worst_target_angle(field, kT, targets, constant), 1e-14) << to_string(m);
  }
}

TEST(OrientationField, LinearTangentFieldIsReproducedByTrilinearInterpolation) {
  // D(p) = exp(B (p - centre)) M on a grid symmetric about its centre: sum of the tangent
  // vectors at M is zero, so M is their mean and v(p) = B (p - centre) is what is interpolated.
  const Eigen::Matrix3d M = rotation_exp(Eigen::Vector3d(-1e-3, 4e-3, 2e-3));
  Eigen::Matrix3d B;
  B << 0.02, -0.01, 0.005, 0.0, 0.03, -0.02, 0.01, 0.0, -0.015;  // rad per m
  const Eigen::Vector3d origin(0.3, -0.1, 0.1);
  const Eigen::Vector3d centre = origin + Eigen::Vector3d::Constant(0.05 * 2.5);
  const auto linear = [&](const Eigen::Vector3d& p) {
    return Eigen::Matrix3d(rotation_exp(B * (p - centre)) * M);
  };
  const Points3 fiducials = testing::grid_points(6, 6, 6, Eigen::Vector3d::Constant(0.05), origin);
  const OrientationCell c = cell(fiducials, kT, linear);
  const Points3 residuals = rotation_residuals_rad(kT.rotation, c.measured, c.commanded);
  CorrectorOptions options;
  options.interpolation.method = InterpolationMethod::kLinear;  // a complete grid: trilinear
  const Corrector positions = Corrector::fit(c.data, options);
  const OrientationCorrector field = OrientationCorrector::fit(positions, c.data, residuals);
  EXPECT_LT(rotation_angle_rad(field.mean_residual(), M), 1e-14);
  Random rng(17);
  Points3 targets(3, 50);
  for (Eigen::Index t = 0; t < targets.cols(); ++t) {
    targets.col(t) = origin + Eigen::Vector3d(rng.uniform(), rng.uniform(), rng.uniform()) * 0.25;
  }
  EXPECT_LT(worst_target_angle(field, kT, targets, linear), 1e-13);
}

// The tangent field's values are rotation vectors: its description prints their sizes in mrad
// and urad (kriging's signal and nugget, rbf's leave-one-out RMS, a table's deviation), lengths
// still in mm; the same after a restore.
TEST(OrientationField, DescriptionsPrintRotationsInRadians) {
  const Eigen::Vector3d origin(0.3, -0.1, 0.1);
  const auto wavy = [&origin](const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - origin;
    return Eigen::Matrix3d(rotation_exp(
        Eigen::Vector3d(2e-3 * std::sin(9.0 * d.x()), 1e-3 * std::cos(7.0 * d.y()), 3e-3 * d.z())));
  };
  const Points3 fiducials = testing::grid_points(6, 6, 6, Eigen::Vector3d::Constant(0.05), origin);
  const OrientationCell c = cell(fiducials, kT, wavy);
  const Points3 residuals = rotation_residuals_rad(kT.rotation, c.measured, c.commanded);
  for (const InterpolationMethod m : {InterpolationMethod::kKriging, InterpolationMethod::kRbf}) {
    for (const bool tabulate : {false, true}) {
      CorrectorOptions options;
      options.interpolation.method = m;
      options.tabulate = tabulate;
      const Corrector positions = Corrector::fit(c.data, options);
      const OrientationCorrector field = OrientationCorrector::fit(positions, c.data, residuals);
      const std::string text = field.describe();
      SCOPED_TRACE(text);
      if (m == InterpolationMethod::kKriging) {
        EXPECT_NE(text.find(" mrad, nugget = "), std::string::npos);
        EXPECT_EQ(text.find(" mm, nugget"), std::string::npos);
        EXPECT_NE(text.find(" mm, s = "), std::string::npos);  // the length scales stay lengths
      } else {
        // "...; LOO RMS a b c mrad" up to the next ';' or ','.
        const std::size_t loo = text.find("LOO RMS");
        ASSERT_NE(loo, std::string::npos);
        const std::string rms = text.substr(loo, text.find_first_of(";,", loo) - loo);
        EXPECT_EQ(rms.substr(rms.size() - 5), " mrad") << rms;
      }
      EXPECT_EQ(text.find(" um"), std::string::npos);
      if (tabulate && text.find("tabulated") != std::string::npos) {
        EXPECT_NE(text.find(" urad of the model (RMS "), std::string::npos);
      }
      if (m == InterpolationMethod::kKriging) {
        EXPECT_NE(positions.describe().find(" mm, nugget = "), std::string::npos);
      } else {
        EXPECT_EQ(positions.describe().find("mrad"), std::string::npos);
      }
      const OrientationCorrector restored =
          OrientationCorrector::restore(field.save(), positions, c.data, residuals);
      EXPECT_EQ(restored.describe(), text);
    }
  }
}

TEST(OrientationField, AFieldNotBetterThanNoneIsKeptButNotApplied) {
  // Residuals that are noise about the identity: interpolating them adds the neighbours' noise
  // to each point's own, so the cross-validated RMS angle is above the uncorrected one.
  Random noise(23);
  std::vector<Eigen::Matrix3d> drawn;
  const Points3 fiducials = testing::grid_points(6, 6, 6, Eigen::Vector3d::Constant(0.05),
                                                 Eigen::Vector3d(0.3, -0.1, 0.1));
  for (Eigen::Index j = 0; j < fiducials.cols(); ++j) drawn.push_back(rotation_exp(noise.normal3(5e-4)));
  std::size_t next = 0;
  const auto noisy = [&](const Eigen::Vector3d&) { return drawn[next++ % drawn.size()]; };
  const OrientationCell c = cell(fiducials, kT, noisy);
  const Points3 residuals = rotation_residuals_rad(kT.rotation, c.measured, c.commanded);
  for (const InterpolationMethod m :
       {InterpolationMethod::kTrilinear, InterpolationMethod::kScattered}) {
    CorrectorOptions options;
    options.interpolation.method = m;
    const Corrector positions = Corrector::fit(c.data, options);
    const OrientationCorrector field = OrientationCorrector::fit(positions, c.data, residuals);
    EXPECT_FALSE(field.applied()) << to_string(m);
    EXPECT_GE(field.cv_rms_rad(), field.uncorrected_rms_rad()) << to_string(m);
    const Points3 targets = testing::grid_points(3, 3, 3, Eigen::Vector3d::Constant(0.07),
                                                 Eigen::Vector3d(0.33, -0.07, 0.13));
    const Points3 sensor_m = kT.rigid().inverse().apply_all(targets);
    std::vector<Eigen::Matrix3d> measured(static_cast<std::size_t>(targets.cols()),
                                          Eigen::Matrix3d::Identity());
    const OrientationCorrection o =
        field.correct(CorrectionQuery(sensor_m, targets, Eigen::MatrixXd(0, 0)), measured);
    for (std::size_t t = 0; t < measured.size(); ++t) {
      EXPECT_EQ(o.status[t], StencilStatus::kNotBetterThanNone);
      EXPECT_EQ(o.corrected_R_robot_marker[t], o.uncorrected_R_robot_marker[t]);
    }
    EXPECT_EQ(o.n_flagged, targets.cols());
    // Saved and restored, it stays not applied.
    const OrientationCorrector restored =
        OrientationCorrector::restore(field.save(), positions, c.data, residuals);
    EXPECT_FALSE(restored.applied());
  }
}

TEST(OrientationField, CountsAndValuesAreChecked) {
  const Points3 fiducials = testing::grid_points(3, 3, 3, Eigen::Vector3d::Constant(0.05));
  const auto identity = [](const Eigen::Vector3d&) {
    return Eigen::Matrix3d(Eigen::Matrix3d::Identity());
  };
  const OrientationCell c = cell(fiducials, kT, identity);
  EXPECT_THROW(rotation_residuals_rad(kT.rotation, c.measured, std::span(c.commanded).first(3)),
               InputError);
  CorrectorOptions options;
  options.interpolation.method = InterpolationMethod::kScattered;
  const Corrector positions = Corrector::fit(c.data, options);
  const Points3 residuals = rotation_residuals_rad(kT.rotation, c.measured, c.commanded);
  EXPECT_THROW(OrientationCorrector::fit(positions, c.data, residuals.leftCols(5)), InputError);
  Points3 bad = residuals;
  bad(0, 0) = std::nan("");
  EXPECT_THROW(OrientationCorrector::fit(positions, c.data, bad), InputError);
  const OrientationCorrector field = OrientationCorrector::fit(positions, c.data, residuals);
  const Points3 one = Points3::Constant(3, 1, 0.02);
  EXPECT_THROW((void)field.correct(CorrectionQuery(one), std::vector<Eigen::Matrix3d>{}), InputError);
}

}  // namespace
}  // namespace vrreg
