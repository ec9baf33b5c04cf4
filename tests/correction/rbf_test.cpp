// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/rbf.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "correction/rbf_loo.hpp"
#include "field_test_support.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

using testing::quadratic_field;
using testing::uniform_box;

Points3 without(const Points3& p, Eigen::Index skip) {
  Points3 out(3, p.cols() - 1);
  out << p.leftCols(skip), p.rightCols(p.cols() - skip - 1);
  return out;
}

// Rippa's closed form (with smoothing) against refitting without each fiducial in turn.
TEST(Rbf, LeaveOneOutEqualsBruteForceRefits) {
  Random rng(11);
  const Points3 p = uniform_box(rng, 30, 0.2);
  const Points3 values = 1e-4 * Points3::Random(3, 30);
  for (const int degree : {1, 2}) {
    const detail::TrendFrame frame = detail::trend_frame(p);
    const detail::RbfSpectrum spectrum(p, degree, frame);
    const Eigen::VectorXd y = values.row(0).transpose();
    for (const double lambda : {0.0, 1e-3 * spectrum.scale(), spectrum.scale()}) {
      const Eigen::VectorXd loo = spectrum.loo_residuals(y, lambda);
      for (Eigen::Index i = 0; i < p.cols(); ++i) {
        const Points3 rest = without(p, i);
        Eigen::VectorXd y_rest(29);
        y_rest << y.head(i), y.tail(29 - i);
        const detail::RbfAxis fit = detail::solve_rbf_direct(rest, y_rest, degree, frame, lambda);
        const double predicted = detail::evaluate_rbf(fit, rest, degree, frame, p.col(i))(0);
        EXPECT_NEAR(loo(i), y(i) - predicted, 1e-9 * 1e-4) << degree << " " << lambda << " " << i;
      }
    }
  }
}

TEST(Rbf, SpectralSolveEqualsTheSaddlePointSystem) {
  Random rng(12);
  const Points3 p = uniform_box(rng, 40, 0.2);
  const Eigen::VectorXd y = 1e-4 * Eigen::VectorXd::Random(40);
  const detail::TrendFrame frame = detail::trend_frame(p);
  const detail::RbfSpectrum spectrum(p, 1, frame);
  const double lambda = 1e-2 * spectrum.scale();
  const detail::RbfAxis a = spectrum.solve(y, lambda);
  const detail::RbfAxis b = detail::solve_rbf_direct(p, y, 1, frame, lambda);
  const Points3 query = uniform_box(rng, 10, 0.2);
  EXPECT_LT((detail::evaluate_rbf(a, p, 1, frame, query) -
             detail::evaluate_rbf(b, p, 1, frame, query))
                .cwiseAbs()
                .maxCoeff(),
            1e-10 * 1e-4);
}

// The polynomial term is not smoothed: a quadratic field is reproduced at any smoothing.
TEST(Rbf, ReproducesAQuadraticFieldWithDegreeTwo) {
  Random rng(13);
  const Points3 p = uniform_box(rng, 60, 0.3);
  const Points3 query = uniform_box(rng, 20, 0.3);
  RbfOptions options;
  options.polynomial_degree = 2;
  const RbfModel model = RbfModel::fit(p, quadratic_field(p), options);
  EXPECT_LT((model.predict(query).mean_m - quadratic_field(query)).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_LT(model.cv_rms_m().maxCoeff(), 1e-11);
}

TEST(Rbf, InterpolatesWithoutSmoothing) {
  Random rng(14);
  const Points3 p = uniform_box(rng, 40, 0.2);
  const Points3 values = 1e-4 * Points3::Random(3, 40);
  RbfOptions options;
  options.n_smoothing = 1;
  options.min_log10_smoothing = options.max_log10_smoothing = -14.0;
  const RbfModel model = RbfModel::fit(p, values, options);
  EXPECT_LT((model.predict(p).mean_m - values).cwiseAbs().maxCoeff(), 1e-8 * 1e-4);
}

// The smoothing chosen on noisy data beats interpolation, and local prediction stays close to
// the global model (measured: RMS difference 12 % of the noise sd, held to 15 %).
TEST(Rbf, SmoothsNoiseAndLocalIsCloseToGlobal) {
  Random rng(15);
  Points3 p(3, 343);
  Eigen::Index c = 0;
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 7; ++i) p.col(c++) = 0.03 * Eigen::Vector3d(i, j, k);
  Points3 noisy = quadratic_field(p);
  for (Eigen::Index j = 0; j < p.cols(); ++j) {
    noisy.col(j) += rng.normal3(2e-5) +
                    1e-4 * Eigen::Vector3d::Constant(std::sin(20.0 * p(0, j) + 10.0 * p(1, j)));
  }
  const RbfModel global = RbfModel::fit(p, noisy);
  EXPECT_TRUE(global.exact());
  EXPECT_GT(global.smoothing().minCoeff(), 0.0);
  EXPECT_LT(global.cv_rms_m().maxCoeff(), 2e-5 * 1.3);
  RbfOptions local_options;
  local_options.exact_limit = 200;
  local_options.local_neighbours = 100;
  const RbfModel local = RbfModel::fit(p, noisy, local_options);
  EXPECT_FALSE(local.exact());
  const Points3 query = uniform_box(rng, 30, 0.18);
  const Points3 diff = local.predict(query).mean_m - global.predict(query).mean_m;
  EXPECT_LT(std::sqrt(diff.squaredNorm() / 90.0), 0.15 * 2e-5);
  // The smoothing chosen on a smaller block of the same density predicts as closely.
  local_options.smoothing_block = 120;
  const RbfModel small_block = RbfModel::fit(p, noisy, local_options);
  const Points3 diff_small = small_block.predict(query).mean_m - global.predict(query).mean_m;
  EXPECT_LT(std::sqrt(diff_small.squaredNorm() / 90.0), 0.15 * 2e-5);
}

TEST(Rbf, RejectsDegenerateInput) {
  Random rng(16);
  Points3 p = uniform_box(rng, 30, 0.2);
  const Points3 values = 1e-4 * Points3::Random(3, 30);
  RbfOptions degree0;
  degree0.polynomial_degree = 0;
  EXPECT_THROW((void)RbfModel::fit(p, values, degree0), InputError);
  EXPECT_THROW((void)RbfModel::fit(p.leftCols(4), values.leftCols(4)), InputError);
  Points3 twin = p;
  twin.col(3) = twin.col(9);
  EXPECT_THROW((void)RbfModel::fit(twin, values), InputError);
  Points3 planar = p;
  planar.row(2).setZero();
  EXPECT_THROW((void)RbfModel::fit(planar, values), InputError);
  Points3 bad = values;
  bad(0, 0) = std::nan("");
  EXPECT_THROW((void)RbfModel::fit(p, bad), InputError);
  RbfOptions tiny_block;
  tiny_block.smoothing_block = 4;  // not more than degree 1's 4 terms
  EXPECT_THROW((void)RbfModel::fit(p, values, tiny_block), InputError);
}

}  // namespace
}  // namespace vrreg
