// SPDX-License-Identifier: Apache-2.0
// Leave-one-out for exact universal kriging: the closed form (Dubrule 1983) against refitting
// without each fiducial, and the latent-sd calibration it drives against Monte Carlo.
#include <gtest/gtest.h>

#include <cmath>

#include "correction/kriging_loo.hpp"
#include "correction/kriging_posterior.hpp"
#include "field_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/correction/kriging.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::gp_draw;
using testing::uniform_box;

const KrigingHyperparameters kField{Eigen::Vector3d(0.08, 0.12, 0.2), 1e-4, 2e-5};

// Closed form = condition on the other J - 1 fiducials (trend re-estimated) and predict at the
// left-out one: residual and predictive variance (latent + nugget^2), for trend degrees 0-2.
TEST(KrigingLeaveOneOut, ClosedFormEqualsRefittingWithoutEachFiducial) {
  Random rng(31);
  const Points3 p = uniform_box(rng, 40, 0.3);
  Eigen::VectorXd y = gp_draw(rng, p, kField, KrigingKernel::matern52);
  for (Eigen::Index j = 0; j < y.size(); ++j) y(j) += rng.normal(kField.nugget_sd_m) + 3e-4 * p(0, j);
  for (const int degree : {0, 1, 2}) {
    const detail::TrendFrame frame = detail::trend_frame(p);
    const detail::KrigingPosterior all =
        detail::condition_kriging(p, y, kField, KrigingKernel::matern52, degree, frame);
    const detail::KrigingLeaveOneOut loo = detail::leave_one_out(all);
    for (Eigen::Index i = 0; i < p.cols(); ++i) {
      Points3 others(3, p.cols() - 1);
      Eigen::VectorXd y_others(p.cols() - 1);
      for (Eigen::Index j = 0, k = 0; j < p.cols(); ++j) {
        if (j == i) continue;
        others.col(k) = p.col(j);
        y_others(k++) = y(j);
      }
      const detail::KrigingPosterior post =
          detail::condition_kriging(others, y_others, kField, KrigingKernel::matern52, degree, frame);
      Eigen::RowVectorXd mean(1), sd(1);
      detail::predict_kriging(post, p.col(i), mean, sd);
      const double variance = sd(0) * sd(0) + kField.nugget_sd_m * kField.nugget_sd_m;
      EXPECT_NEAR(loo.residual_m(i), y(i) - mean(0), 1e-9 * std::sqrt(variance))
          << "degree " << degree << " i " << i;
      EXPECT_NEAR(loo.variance_m2(i), variance, 1e-8 * variance) << "degree " << degree << " i " << i;
    }
  }
}

struct Draw {
  Points3 fiducials, held_out, values, held_out_values;
};

// A field drawn from kField (latent + nugget noise) at 250 fiducials and 150 new points.
Draw draw(Random& rng) {
  Draw d;
  d.fiducials = uniform_box(rng, 250, 0.3);
  d.held_out = uniform_box(rng, 150, 0.3);
  Points3 all(3, 400);
  all << d.fiducials, d.held_out;
  d.values.resize(3, 250);
  d.held_out_values.resize(3, 150);
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::VectorXd v = gp_draw(rng, all, kField, KrigingKernel::matern52);
    for (Eigen::Index j = 0; j < v.size(); ++j) v(j) += rng.normal(kField.nugget_sd_m);
    d.values.row(axis) = v.head(250).transpose();
    d.held_out_values.row(axis) = v.tail(150).transpose();
  }
  return d;
}

// RMS over new points of (value - mean) / sqrt(sd^2 + nugget^2): 1 when the sd is honest.
double z_rms(const KrigingModel& model, const Draw& d) {
  const FieldPrediction p = model.predict(d.held_out);
  double sum = 0.0;
  for (Eigen::Index j = 0; j < p.mean_m.cols(); ++j) {
    for (int axis = 0; axis < 3; ++axis) {
      const double nugget = model.nugget_sd_m()(axis);
      const double v = p.sd_m(axis, j) * p.sd_m(axis, j) + nugget * nugget;
      const double e = d.held_out_values(axis, j) - p.mean_m(axis, j);
      sum += e * e / v;
    }
  }
  return std::sqrt(sum / static_cast<double>(3 * p.mean_m.cols()));
}

// A model told a signal sd three times the truth overstates its latent sd (uncalibrated z RMS
// ~0.78: the nugget, known, is part of every error); the leave-one-out factor brings it back to ~1
// on new points. With the true hyperparameters the factor stays 1 (within the z-scores' sampling
// noise). 3 draws x 3 axes x 150 points.
TEST(KrigingLeaveOneOut, ScaleRepairsAMisstatedSignalSd) {
  KrigingHyperparameters wrong = kField;
  wrong.signal_sd_m *= 3.0;
  double sum_z2_raw = 0.0, sum_z2_calibrated = 0.0, sum_z2_true = 0.0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    Random rng(40 + seed);
    const Draw d = draw(rng);
    KrigingOptions raw_options;
    raw_options.loo_sd_calibration = false;
    const double raw =
        z_rms(KrigingModel::with_hyperparameters(d.fiducials, d.values, {wrong, wrong, wrong},
                                                 raw_options),
              d);
    const KrigingModel calibrated =
        KrigingModel::with_hyperparameters(d.fiducials, d.values, {wrong, wrong, wrong});
    const KrigingModel truth =
        KrigingModel::with_hyperparameters(d.fiducials, d.values, {kField, kField, kField});
    for (const KrigingAxisFit& axis : calibrated.axes()) {
      EXPECT_GT(axis.latent_sd_scale, 0.3);
      EXPECT_LT(axis.latent_sd_scale, 0.8);
    }
    for (const KrigingAxisFit& axis : truth.axes()) EXPECT_EQ(axis.latent_sd_scale, 1.0);
    sum_z2_raw += raw * raw;
    sum_z2_calibrated += std::pow(z_rms(calibrated, d), 2);
    sum_z2_true += std::pow(z_rms(truth, d), 2);
  }
  const double raw = std::sqrt(sum_z2_raw / 3), calibrated = std::sqrt(sum_z2_calibrated / 3),
               truth = std::sqrt(sum_z2_true / 3);
  EXPECT_LT(raw, 0.85);
  EXPECT_GT(calibrated, 0.88);
  EXPECT_LT(calibrated, 1.12);
  EXPECT_GT(truth, 0.88);
  EXPECT_LT(truth, 1.12);
  std::printf("z RMS: uncalibrated %.3f, calibrated %.3f, true hyperparameters %.3f\n", raw,
              calibrated, truth);
}

// Given factors are used as they are (a refitted model keeps its parent's); the means never
// change; bad factors are refused; local models keep 1.
TEST(KrigingLeaveOneOut, GivenScalesMeansAndLocalModels) {
  Random rng(50);
  const Draw d = draw(rng);
  KrigingOptions given;
  given.latent_sd_scale = std::array<double, 3>{0.5, 2.0, 1.0};
  KrigingHyperparameters wrong = kField;
  wrong.signal_sd_m *= 3.0;
  const auto hyper = std::array<KrigingHyperparameters, 3>{wrong, wrong, wrong};
  KrigingOptions raw_options;
  raw_options.loo_sd_calibration = false;
  const KrigingModel raw = KrigingModel::with_hyperparameters(d.fiducials, d.values, hyper, raw_options);
  const KrigingModel scaled = KrigingModel::with_hyperparameters(d.fiducials, d.values, hyper, given);
  const KrigingModel calibrated = KrigingModel::with_hyperparameters(d.fiducials, d.values, hyper);
  const FieldPrediction a = raw.predict(d.held_out), b = scaled.predict(d.held_out),
                        c = calibrated.predict(d.held_out);
  EXPECT_TRUE(a.mean_m == b.mean_m);
  EXPECT_TRUE(a.mean_m == c.mean_m);
  EXPECT_TRUE(b.sd_m.row(0) == 0.5 * a.sd_m.row(0));
  EXPECT_TRUE(b.sd_m.row(1) == 2.0 * a.sd_m.row(1));
  EXPECT_TRUE(b.sd_m.row(2) == a.sd_m.row(2));
  EXPECT_NE(calibrated.describe().find("sd x"), std::string::npos);
  EXPECT_EQ(raw.describe().find("sd x"), std::string::npos);

  KrigingOptions bad;
  bad.latent_sd_scale = std::array<double, 3>{1.0, 0.0, 1.0};
  EXPECT_THROW(static_cast<void>(KrigingModel::with_hyperparameters(d.fiducials, d.values, hyper, bad)),
               InputError);
  bad.latent_sd_scale = std::array<double, 3>{1.0, std::nan(""), 1.0};
  EXPECT_THROW(static_cast<void>(KrigingModel::with_hyperparameters(d.fiducials, d.values, hyper, bad)),
               InputError);

  KrigingOptions local;
  local.exact_limit = 100;
  local.local_neighbours = 60;
  const KrigingModel local_model =
      KrigingModel::with_hyperparameters(d.fiducials, d.values, hyper, local);
  ASSERT_FALSE(local_model.exact());
  for (const KrigingAxisFit& axis : local_model.axes()) EXPECT_EQ(axis.latent_sd_scale, 1.0);
}

// Below the smallest factor (residuals smaller than the nugget alone explains) and above the
// largest, the factor is clamped; without latent variance left it is 1.
TEST(KrigingLeaveOneOut, ScaleIsClampedAndNeedsLatentVariance) {
  detail::KrigingLeaveOneOut loo;
  loo.residual_m = Eigen::VectorXd::Constant(400, 1e-6);
  loo.variance_m2 = Eigen::VectorXd::Constant(400, 2e-8);  // latent 1e-8 + nugget 1e-8
  EXPECT_EQ(detail::loo_latent_sd_scale(loo, 1e-4), detail::kMinLatentSdScale);
  loo.residual_m.setConstant(1.0);
  EXPECT_EQ(detail::loo_latent_sd_scale(loo, 1e-4), detail::kMaxLatentSdScale);
  // mean z^2 = r^2 / (c^2 * 1e-8 + 1e-8) = 1 at c = 2 for r^2 = 5e-8.
  loo.residual_m.setConstant(std::sqrt(5e-8));
  EXPECT_NEAR(detail::loo_latent_sd_scale(loo, 1e-4), 2.0, 1e-12);
  loo.variance_m2.setConstant(1e-8);  // nugget only
  EXPECT_EQ(detail::loo_latent_sd_scale(loo, 1e-4), 1.0);
  // Within 3 standard errors (3 sqrt(2 / 400) = 0.21) of a unit mean square: unchanged.
  loo.variance_m2.setConstant(2e-8);
  loo.residual_m.setConstant(std::sqrt(1.2 * 2e-8));
  EXPECT_EQ(detail::loo_latent_sd_scale(loo, 1e-4), 1.0);
  loo.residual_m.setConstant(std::sqrt(1.25 * 2e-8));
  EXPECT_GT(detail::loo_latent_sd_scale(loo, 1e-4), 1.0);
}

}  // namespace
}  // namespace vrreg
