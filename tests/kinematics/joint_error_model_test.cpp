// SPDX-License-Identifier: Apache-2.0
// The joint-space error model on robots whose error it can represent exactly (DH deltas, joint
// offsets, polynomial joint errors, a marker offset): predictions at held-out joints recovered to
// 1e-9 m, with and without noise; bad input reported.
#include "vrreg/kinematics/joint_error_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "kinematics/joint_error_solve.hpp"
#include "kinematics_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg::kinematics {
namespace {

using testing::marker_at;

// A robot whose error lies in the model: DH rows off by `scale` (m or rad), each joint's angle off
// by a cubic in (q - q0) with coefficients of size `scale`, the marker off by `scale` metres.
struct TruthRobot {
  SerialChain nominal;
  SerialChain actual;
  Eigen::Vector3d p_marker_m;
  Eigen::Vector3d p_marker_actual_m;
  JointVector q0;
  Eigen::MatrixXd cubic;  // n x 4

  Eigen::Vector3d error_m(const JointVector& q) const {
    JointVector qa = q;
    for (int i = 0; i < q.size(); ++i) {
      const double t = q(i) - q0(i);
      qa(i) += cubic(i, 0) + t * (cubic(i, 1) + t * (cubic(i, 2) + t * cubic(i, 3)));
    }
    return marker_at(actual, qa, p_marker_actual_m) - marker_at(nominal, q, p_marker_m);
  }
};

TruthRobot make_truth(double scale, std::uint64_t seed) {
  Random rng(seed);
  const SerialChain nominal =
      ur5().with_tool(Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, 0.06)));
  std::vector<DhRow> rows = nominal.rows();
  for (DhRow& r : rows) {
    r.a_m += rng.normal(scale);
    r.d_m += rng.normal(scale);
    r.alpha_rad += rng.normal(scale);
  }
  JointVector q0(6);
  q0 << 0.5, -1.4, 1.6, -1.8, -1.57, 0.3;
  Eigen::MatrixXd cubic(6, 4);
  for (Eigen::Index k = 0; k < cubic.size(); ++k) cubic(k) = rng.normal(scale);
  // Off the last joint's axis, so that joint 6's error moves the marker (on the axis it cannot be
  // seen at first order and the model leaves it out).
  const Eigen::Vector3d p(0.03, -0.02, 0.06);
  return TruthRobot{
      nominal,
      SerialChain("actual", rows, nominal.limits(), nominal.T_base_dh0(), nominal.T_flange_tcp()),
      p,
      p + rng.normal3(scale),
      q0,
      cubic};
}

std::vector<JointVector> joints_near(const JointVector& q0, double half_width_rad, int n,
                                     Random& rng) {
  std::vector<JointVector> out;
  for (int j = 0; j < n; ++j) {
    JointVector q = q0;
    for (int i = 0; i < q.size(); ++i) q(i) += rng.uniform(-half_width_rad, half_width_rad);
    out.push_back(q);
  }
  return out;
}

Points3 errors_of(const TruthRobot& t, const std::vector<JointVector>& q) {
  Points3 e(3, static_cast<Eigen::Index>(q.size()));
  for (std::size_t j = 0; j < q.size(); ++j) e.col(static_cast<Eigen::Index>(j)) = t.error_m(q[j]);
  return e;
}

double max_prediction_error_m(const JointErrorModel& m, const TruthRobot& t,
                              const std::vector<JointVector>& q) {
  return (m.predict_m(q) - errors_of(t, q)).colwise().norm().maxCoeff();
}

JointErrorModelOptions cubic_options(int gauss_newton_iterations) {
  JointErrorModelOptions o;
  o.joint_degrees.assign(6, 3);
  o.gauss_newton_iterations = gauss_newton_iterations;
  return o;
}

TEST(JointErrorModel, GaussNewtonRecoversItsOwnNonlinearModelExactly) {
  // The truth is the model's exact (perturbed-chain) form with random parameters of ~1e-3 on the
  // identifiable columns: its second-order terms (~1e-6 m) are what Gauss-Newton must get right.
  const TruthRobot truth = make_truth(0.0, 21);
  Random rng(22);
  const std::vector<JointVector> fid = joints_near(truth.q0, 0.3, 300, rng);
  const std::vector<JointVector> tgt = joints_near(truth.q0, 0.25, 50, rng);
  const JointErrorModelOptions o = cubic_options(10);
  JointErrorModel::State s =
      make_joint_error_state(truth.nominal, fid, Points3::Zero(3, 300), o, truth.p_marker_m);
  s.layout.degrees = o.joint_degrees;
  Eigen::VectorXd x_true = Eigen::VectorXd::Zero(s.layout.n_columns());
  const Eigen::MatrixXd a0 = design_matrix(s, x_true, fid);
  for (const Eigen::Index c : independent_columns(a0, o.relative_rank_tolerance)) {
    x_true(c) = rng.normal(c >= s.layout.trend_column() ? 1e-4 : 1e-3);
  }
  const SerialChain chain_true = perturbed_chain(s, x_true);
  auto truth_errors = [&](const std::vector<JointVector>& q) {
    Points3 e(3, static_cast<Eigen::Index>(q.size()));
    for (std::size_t j = 0; j < q.size(); ++j) {
      e.col(static_cast<Eigen::Index>(j)) = model_error_m(s, chain_true, x_true, q[j]);
    }
    return e;
  };
  const Points3 e = truth_errors(fid);
  const JointErrorModel m = JointErrorModel::fit(truth.nominal, fid, e, o, truth.p_marker_m);
  EXPECT_LT(m.residual_rms_m(), 1e-11);
  EXPECT_LT((m.predict_m(tgt) - truth_errors(tgt)).colwise().norm().maxCoeff(), 1e-10);
  EXPECT_LT(m.rank(), m.n_parameters());  // base rotation vs joint-1 offset vs trend, etc.
  // The first-order model alone leaves the second-order terms, ~1e-6 m.
  const JointErrorModel linear =
      JointErrorModel::fit(truth.nominal, fid, e, cubic_options(0), truth.p_marker_m);
  const double first_order_m =
      (linear.predict_m(tgt) - truth_errors(tgt)).colwise().norm().maxCoeff();
  EXPECT_GT(first_order_m, 1e-8);
  EXPECT_LT(first_order_m, 2e-5);
}

TEST(JointErrorModel, GaussNewtonRecoversAPerturbedRobotToItsRedundancy) {
  // An independent truth: every DH row, joint and the marker off by ~1e-3. Parameters redundant
  // at first order (d of parallel joints, ...) are left out of the fit, so the part of the error
  // only they explain at second order (~(1e-3)^2 x 0.03 m) remains; everything else is fitted.
  const TruthRobot truth = make_truth(1e-3, 11);
  Random rng(12);
  const std::vector<JointVector> fid = joints_near(truth.q0, 0.3, 300, rng);
  const std::vector<JointVector> tgt = joints_near(truth.q0, 0.25, 50, rng);
  const Points3 e = errors_of(truth, fid);
  const JointErrorModel m =
      JointErrorModel::fit(truth.nominal, fid, e, cubic_options(8), truth.p_marker_m);
  EXPECT_LT(max_prediction_error_m(m, truth, tgt), 1e-7);
  const JointErrorModel linear =
      JointErrorModel::fit(truth.nominal, fid, e, cubic_options(0), truth.p_marker_m);
  EXPECT_GT(max_prediction_error_m(linear, truth, tgt),
            5.0 * max_prediction_error_m(m, truth, tgt));
}

TEST(JointErrorModel, FirstOrderRecoversTinyErrors) {
  // Errors of 1e-6: second-order terms ~(1e-6)^2 * 1 m = 1e-12 m, far below the 1e-9 tolerance.
  const TruthRobot truth = make_truth(1e-6, 13);
  Random rng(14);
  const std::vector<JointVector> fid = joints_near(truth.q0, 0.3, 200, rng);
  const std::vector<JointVector> tgt = joints_near(truth.q0, 0.25, 50, rng);
  const JointErrorModel m = JointErrorModel::fit(truth.nominal, fid, errors_of(truth, fid),
                                                 cubic_options(0), truth.p_marker_m);
  EXPECT_LT(max_prediction_error_m(m, truth, tgt), 1e-9);
  for (const JointVector& q : tgt) {  // one-point and batch predictions agree
    EXPECT_LT((m.predict_m(q) - m.predict_m(std::vector<JointVector>{q}).col(0)).norm(), 1e-15);
  }
}

TEST(JointErrorModel, NoisyFiducialsResidualAndCvMatchTheNoise) {
  const TruthRobot truth = make_truth(1e-3, 15);
  Random rng(16);
  const std::vector<JointVector> fid = joints_near(truth.q0, 0.3, 400, rng);
  constexpr double kSigma = 20e-6;  // per axis
  Points3 e = errors_of(truth, fid);
  for (Eigen::Index j = 0; j < e.cols(); ++j) e.col(j) += rng.normal3(kSigma);
  const JointErrorModelOptions o = cubic_options(3);
  const JointErrorModel m = JointErrorModel::fit(truth.nominal, fid, e, o, truth.p_marker_m);
  // Least squares leaves sigma^2 (3J - rank) / J per point; CV predicts fresh noise plus the
  // estimate's own error, sigma^2 (3 + ~rank/J).
  const double n = static_cast<double>(fid.size());
  const double expected_residual = kSigma * std::sqrt((3.0 * n - m.rank()) / n);
  EXPECT_NEAR(m.residual_rms_m(), expected_residual, 0.1 * expected_residual);
  const double cv = joint_error_cv_rms_m(truth.nominal, fid, e, o, truth.p_marker_m);
  const double expected_cv = kSigma * std::sqrt(3.0 + m.rank() / (0.8 * n));
  EXPECT_NEAR(cv, expected_cv, 0.12 * expected_cv);
}

TEST(JointErrorModel, DegreeChoiceByCrossValidationFindsTheCubics) {
  const TruthRobot truth = make_truth(1e-3, 17);
  Random rng(18);
  const std::vector<JointVector> fid = joints_near(truth.q0, 0.3, 300, rng);
  const std::vector<JointVector> tgt = joints_near(truth.q0, 0.25, 50, rng);
  JointErrorModelOptions o;
  o.max_joint_degree = 8;
  const JointErrorModel m =
      JointErrorModel::fit(truth.nominal, fid, errors_of(truth, fid), o, truth.p_marker_m);
  ASSERT_EQ(m.joint_degrees().size(), 6u);
  EXPECT_LT(m.selection_cv_rms_m(), 1e-6);  // first-order CV: the second-order terms remain
  // The choice is by the first-order CV, whose floor here is the ~1e-6 m second-order terms.
  EXPECT_LT(max_prediction_error_m(m, truth, tgt), 1e-6);
  // Same input, same model, bit for bit.
  const JointErrorModel again =
      JointErrorModel::fit(truth.nominal, fid, errors_of(truth, fid), o, truth.p_marker_m);
  EXPECT_EQ(again.joint_degrees(), m.joint_degrees());
  EXPECT_EQ(again.parameters(), m.parameters());
}

// A joint sampled at few distinct angles (a grid column shares q1) cannot carry a high degree:
// a polynomial through them is free in between, and cross-validation on fiducials that share
// those angles cannot see it. The degree is capped at a third of the distinct angles.
TEST(JointErrorModel, DegreeIsCappedByTheDistinctAnglesOfEachJoint) {
  const TruthRobot truth = make_truth(1e-3, 19);
  Random rng(20);
  std::vector<JointVector> fid = joints_near(truth.q0, 0.3, 300, rng);
  for (std::size_t j = 0; j < fid.size(); ++j) {
    fid[j](0) = truth.q0(0) + 0.05 * static_cast<double>(j % 7);  // 7 distinct q1 values
  }
  JointErrorModelOptions o;
  o.max_joint_degree = 8;
  const JointErrorModel m =
      JointErrorModel::fit(truth.nominal, fid, errors_of(truth, fid), o, truth.p_marker_m);
  EXPECT_LE(m.joint_degrees()[0], 2);  // (7 - 1) / 3
}

TEST(JointErrorModel, BadInputIsReported) {
  const TruthRobot truth = make_truth(1e-3, 19);
  Random rng(20);
  std::vector<JointVector> fid = joints_near(truth.q0, 0.3, 40, rng);
  Points3 e = errors_of(truth, fid);
  const JointErrorModelOptions o = cubic_options(0);
  EXPECT_THROW((void)JointErrorModel::fit(truth.nominal, fid, e.leftCols(39), o), InputError);
  Points3 bad = e;
  bad(1, 7) = std::nan("");
  EXPECT_THROW((void)JointErrorModel::fit(truth.nominal, fid, bad, o), InputError);
  std::vector<JointVector> short_q = fid;
  short_q[3] = short_q[3].head(5).eval();
  EXPECT_THROW((void)JointErrorModel::fit(truth.nominal, short_q, e, o), InputError);
  JointErrorModelOptions wrong = o;
  wrong.joint_degrees.assign(5, 2);
  EXPECT_THROW((void)JointErrorModel::fit(truth.nominal, fid, e, wrong), InputError);
  // 6 fiducials: 18 equations, fewer than the identifiable parameters.
  const std::vector<JointVector> few(fid.begin(), fid.begin() + 6);
  EXPECT_THROW((void)JointErrorModel::fit(truth.nominal, few, e.leftCols(6), o), InputError);
  wrong = o;
  wrong.trend_degree = 3;
  EXPECT_THROW((void)JointErrorModel::fit(truth.nominal, fid, e, wrong), InputError);
}

}  // namespace
}  // namespace vrreg::kinematics
