// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/kriging.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "field_test_support.hpp"
#include "correction/kriging_fit.hpp"
#include "correction/kriging_posterior.hpp"
#include "correction/kriging_reml.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

using testing::gp_draw;
using testing::quadratic_field;
using testing::uniform_box;

std::array<KrigingHyperparameters, 3> three_axes() {
  std::array<KrigingHyperparameters, 3> h;
  h[0] = {Eigen::Vector3d(0.08, 0.12, 0.2), 1e-4, 1e-5};
  h[1] = {Eigen::Vector3d(0.15, 0.06, 0.1), 2e-4, 3e-5};
  h[2] = {Eigen::Vector3d(0.1, 0.1, 0.1), 5e-5, 1e-5};
  return h;
}

// Universal kriging by the textbook formulas with an explicit inverse (independent of the
// Cholesky/triangular-solve implementation).
TEST(Kriging, MeanAndSdEqualTheDenseFormula) {
  Random rng(1);
  const Points3 p = uniform_box(rng, 40, 0.2);
  const Points3 values = quadratic_field(p) + 1e-4 * Points3::Random(3, 40);
  const Points3 query = uniform_box(rng, 15, 0.2);
  const auto hyper = three_axes();
  for (const KrigingKernel kernel : {KrigingKernel::matern52, KrigingKernel::squared_exponential}) {
    KrigingOptions options;
    options.kernel = kernel;
    options.loo_sd_calibration = false;  // the formula's own sd (the factor: kriging_loo_test.cpp)
    const FieldPrediction got =
        KrigingModel::with_hyperparameters(p, values, hyper, options).predict(query);
    const detail::TrendFrame frame = detail::trend_frame(p);
    const Eigen::MatrixXd f = detail::trend_basis(p, 2, frame);
    const Eigen::MatrixXd fq = detail::trend_basis(query, 2, frame);
    for (int axis = 0; axis < 3; ++axis) {
      const KrigingHyperparameters& h = hyper[static_cast<std::size_t>(axis)];
      Eigen::MatrixXd k = detail::covariance(kernel, p, p, h);
      k.diagonal().array() += h.nugget_sd_m * h.nugget_sd_m;
      const Eigen::MatrixXd ki = k.fullPivLu().inverse();
      const Eigen::MatrixXd ai = (f.transpose() * ki * f).fullPivLu().inverse();
      const Eigen::VectorXd y = values.row(axis).transpose();
      const Eigen::VectorXd beta = ai * f.transpose() * ki * y;
      const Eigen::MatrixXd ks = detail::covariance(kernel, p, query, h);
      for (Eigen::Index q = 0; q < query.cols(); ++q) {
        const Eigen::VectorXd kq = ks.col(q);
        const double mean = fq.row(q).dot(beta) + kq.dot(ki * (y - f * beta));
        const Eigen::VectorXd u = fq.row(q).transpose() - f.transpose() * ki * kq;
        const double var = h.signal_sd_m * h.signal_sd_m - kq.dot(ki * kq) + u.dot(ai * u);
        EXPECT_NEAR(got.mean_m(axis, q), mean, 1e-10 * 1e-3) << axis << " " << q;
        EXPECT_NEAR(got.sd_m(axis, q), std::sqrt(var), 1e-10 * h.signal_sd_m) << axis << " " << q;
      }
    }
  }
}

TEST(Kriging, InterpolatesWithZeroNugget) {
  Random rng(2);
  const Points3 p = uniform_box(rng, 30, 0.2);
  const Points3 values = 1e-4 * Points3::Random(3, 30);
  auto hyper = three_axes();
  for (auto& h : hyper) h.nugget_sd_m = 0.0;
  const FieldPrediction got = KrigingModel::with_hyperparameters(p, values, hyper).predict(p);
  EXPECT_LT((got.mean_m - values).cwiseAbs().maxCoeff(), 1e-8 * 1e-4);
  EXPECT_LT(got.sd_m.maxCoeff(), 1e-5 * 1e-4);  // sqrt of a rounding-level variance
}

// A field in the span of the trend has zero residual: reproduced for any hyperparameters.
TEST(Kriging, ReproducesAQuadraticField) {
  Random rng(3);
  const Points3 p = uniform_box(rng, 60, 0.3);
  const Points3 query = uniform_box(rng, 20, 0.3);
  const FieldPrediction fixed =
      KrigingModel::with_hyperparameters(p, quadratic_field(p), three_axes()).predict(query);
  EXPECT_LT((fixed.mean_m - quadratic_field(query)).cwiseAbs().maxCoeff(), 1e-12);
  const FieldPrediction fitted = KrigingModel::fit(p, quadratic_field(p)).predict(query);
  EXPECT_LT((fitted.mean_m - quadratic_field(query)).cwiseAbs().maxCoeff(), 1e-11);
}

TEST(Kriging, RemlGradientMatchesFiniteDifferences) {
  Random rng(4);
  const Points3 p = uniform_box(rng, 35, 0.2);
  Eigen::VectorXd y(35);
  for (Eigen::Index j = 0; j < 35; ++j) y(j) = rng.normal();
  const detail::TrendFrame frame = detail::trend_frame(p);
  for (const KrigingKernel kernel : {KrigingKernel::matern52, KrigingKernel::squared_exponential}) {
    const detail::RemlData data =
        detail::make_reml_data(p, y, detail::trend_basis(p, 2, frame), kernel, 0.04);
    detail::RemlParameters theta;
    theta << std::log(0.07), std::log(0.11), std::log(0.2), std::log(0.9), std::log(0.3);
    detail::RemlParameters gradient;
    (void)detail::restricted_log_likelihood(data, theta, &gradient);
    for (int k = 0; k < 5; ++k) {
      const double step = 1e-5;
      detail::RemlParameters plus = theta;
      detail::RemlParameters minus = theta;
      plus(k) += step;
      minus(k) -= step;
      const double numeric = (detail::restricted_log_likelihood(data, plus, nullptr) -
                              detail::restricted_log_likelihood(data, minus, nullptr)) /
                             (2.0 * step);
      EXPECT_NEAR(gradient(k), numeric, 1e-6 * (1.0 + std::abs(numeric))) << k;
    }
  }
}

TEST(Kriging, RejectsDegenerateInput) {
  Random rng(5);
  const Points3 p = uniform_box(rng, 10, 0.2);
  EXPECT_THROW((void)KrigingModel::fit(p, Points3::Zero(3, 10)), InputError);  // 10 < 11
  Points3 planar = uniform_box(rng, 40, 0.2);
  planar.row(2).setConstant(0.1);
  EXPECT_THROW((void)KrigingModel::fit(planar, 1e-4 * Points3::Random(3, 40)), InputError);
  Points3 good = uniform_box(rng, 40, 0.2);
  Points3 values = 1e-4 * Points3::Random(3, 40);
  values(1, 7) = std::nan("");
  EXPECT_THROW((void)KrigingModel::fit(good, values), InputError);
  EXPECT_THROW((void)KrigingModel::fit(good, Points3::Zero(3, 39)), InputError);
  KrigingOptions no_cluster;
  no_cluster.fit_cluster = 0;
  EXPECT_THROW((void)KrigingModel::fit(good, 1e-4 * Points3::Random(3, 40), no_cluster),
               InputError);
}

// Coincident fiducials with different values: the nugget absorbs them.
TEST(Kriging, CoincidentFiducialsAreAbsorbedByTheNugget) {
  Random rng(6);
  Points3 p = uniform_box(rng, 50, 0.2);
  p.col(1) = p.col(0);
  p.col(2) = p.col(0);
  const Points3 values = quadratic_field(p) + 2e-5 * Points3::Random(3, 50);
  const KrigingModel model = KrigingModel::fit(p, values);
  const FieldPrediction got = model.predict(uniform_box(rng, 5, 0.2));
  EXPECT_TRUE(got.mean_m.allFinite() && got.sd_m.allFinite());
  EXPECT_GT(model.nugget_sd_m().minCoeff(), 0.0);
}

TEST(Kriging, NoiseSdIsALowerBoundOfTheNugget) {
  Random rng(7);
  const Points3 p = uniform_box(rng, 80, 0.2);
  const Points3 values = quadratic_field(p) + 1e-6 * Points3::Random(3, 80);
  KrigingOptions options;
  options.noise_sd_m = 3e-5;
  const KrigingModel model = KrigingModel::fit(p, values, options);
  EXPECT_GE(model.nugget_sd_m().minCoeff(), 3e-5);
}

TEST(Kriging, FitIsDeterministic) {
  Random rng(8);
  const Points3 p = uniform_box(rng, 80, 0.2);
  const Points3 values = quadratic_field(p) + 2e-5 * Points3::Random(3, 80);
  KrigingOptions options;
  options.fit_subset = 50;  // seeded subset
  const FieldPrediction a = KrigingModel::fit(p, values, options).predict(p);
  const FieldPrediction b = KrigingModel::fit(p, values, options).predict(p);
  EXPECT_EQ(a.mean_m, b.mean_m);
  EXPECT_EQ(a.sd_m, b.sd_m);
}

// The hyperparameters' fit subset of a dense grid: clusters of near neighbours, so that the
// shortest pairs of the grid survive (a uniform subset of 500 of 8000 keeps few of them).
TEST(Kriging, FitSubsetKeepsTheGridsShortPairs) {
  Points3 p(3, 8000);
  for (Eigen::Index i = 0; i < p.cols(); ++i)
    p.col(i) = 0.01 * Eigen::Vector3d(static_cast<double>(i % 20), static_cast<double>(i / 20 % 20),
                                      static_cast<double>(i / 400));
  const std::vector<Eigen::Index> subset = detail::seeded_cluster_subset(p, 500, 64, 1);
  ASSERT_EQ(subset.size(), 500U);
  EXPECT_TRUE(std::is_sorted(subset.begin(), subset.end()));
  EXPECT_EQ(std::adjacent_find(subset.begin(), subset.end()), subset.end());
  EXPECT_EQ(subset, detail::seeded_cluster_subset(p, 500, 64, 1));
  EXPECT_NE(subset, detail::seeded_cluster_subset(p, 500, 64, 2));
  const auto with_a_grid_neighbour = [&](const std::vector<Eigen::Index>& s) {
    int count = 0;
    for (const Eigen::Index a : s) {
      for (const Eigen::Index b : s) {
        if ((p.col(a) - p.col(b)).norm() < 0.0101 && a != b) {
          ++count;
          break;
        }
      }
    }
    return count;
  };
  EXPECT_GT(with_a_grid_neighbour(subset), 450);
  EXPECT_LT(with_a_grid_neighbour(detail::seeded_cluster_subset(p, 500, 1, 1)), 200);  // uniform
  // Fewer fiducials than the subset: all of them, and a cluster of 1 is a uniform draw.
  EXPECT_EQ(detail::seeded_cluster_subset(p.leftCols(300), 500, 64, 1).size(), 300U);
  EXPECT_EQ(detail::seeded_cluster_subset(p, 500, 1, 1).size(), 500U);
}

}  // namespace
}  // namespace vrreg
