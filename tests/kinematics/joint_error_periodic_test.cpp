// SPDX-License-Identifier: Apache-2.0
// Periodic (cyclic transmission) terms of the joint-space error model: a short-period joint error
// seen at sparse angles, as on a grid whose columns share q1, is found (period, amplitude) and
// predicted between the sampled angles, where a Legendre series cannot; noise alone adds no term;
// given terms are fitted as they are and bad ones refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kinematics_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg::kinematics {
namespace {

using testing::marker_at;

constexpr double kDeg = std::numbers::pi / 180.0;

// A UR5 whose joints carry cyclic errors A sin(2 pi q / P + phi) (joint 1: 4 deg, joint 3:
// 15 deg, as a harmonic drive and a gear stage) and small zero offsets; nothing else.
struct CyclicRobot {
  SerialChain nominal = ur5().with_tool(Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, 0.06)));
  Eigen::Vector3d p_marker_m{0.03, -0.02, 0.06};
  double amplitude1_rad = 1.0 / 60.0 * kDeg * 1.5;
  double period1_rad = 4.0 * kDeg;
  double amplitude3_rad = 1.5 / 60.0 * kDeg;
  double period3_rad = 15.0 * kDeg;
  JointVector offset_rad = (JointVector(6) << 2e-4, -1e-4, 3e-4, 1e-4, -2e-4, 0.0).finished();

  Eigen::Vector3d error_m(const JointVector& q) const {
    JointVector qa = q + offset_rad;
    qa(0) += amplitude1_rad * std::sin(2.0 * std::numbers::pi * q(0) / period1_rad + 0.7);
    qa(2) += amplitude3_rad * std::sin(2.0 * std::numbers::pi * q(2) / period3_rad + 2.1);
    return marker_at(nominal, qa, p_marker_m) - marker_at(nominal, q, p_marker_m);
  }
  Points3 errors_of(const std::vector<JointVector>& q) const {
    Points3 e(3, static_cast<Eigen::Index>(q.size()));
    for (std::size_t j = 0; j < q.size(); ++j) e.col(static_cast<Eigen::Index>(j)) = error_m(q[j]);
    return e;
  }
};

const JointVector kCentre = (JointVector(6) << 0.5, -1.4, 1.6, -1.8, -1.57, 0.3).finished();

// Joints near kCentre, joint 1 only at the given angles (a grid's columns), the rest random.
std::vector<JointVector> fiducials(const std::vector<double>& q1_values, int per_value,
                                   Random& rng) {
  std::vector<JointVector> out;
  for (const double q1 : q1_values) {
    for (int k = 0; k < per_value; ++k) {
      JointVector q = kCentre;
      for (int i = 1; i < 6; ++i) q(i) += rng.uniform(-0.3, 0.3);
      q(0) = q1;
      out.push_back(q);
    }
  }
  return out;
}

// 24 irregular joint-1 angles over 30 deg (mean spacing 1.3 deg, a third of the 4 deg period).
std::vector<double> sparse_q1(Random& rng) {
  std::vector<double> v;
  for (int k = 0; k < 24; ++k) v.push_back(kCentre(0) + rng.uniform(-15.0, 15.0) * kDeg);
  return v;
}

double rms_prediction_error_m(const JointErrorModel& m, const CyclicRobot& robot,
                              const std::vector<JointVector>& q) {
  const Points3 d = m.predict_m(q) - robot.errors_of(q);
  return std::sqrt(d.colwise().squaredNorm().mean());
}

TEST(JointErrorPeriodic, FindsAShortPeriodBetweenSparseAnglesWhereLegendreCannot) {
  const CyclicRobot robot;
  Random rng(31);
  const std::vector<JointVector> fid = fiducials(sparse_q1(rng), 12, rng);
  Points3 e = robot.errors_of(fid);
  constexpr double kSigma = 10e-6;
  for (Eigen::Index j = 0; j < e.cols(); ++j) e.col(j) += rng.normal3(kSigma);
  // Targets at joint-1 angles no fiducial has: in between the grid's columns.
  std::vector<JointVector> tgt = fiducials(sparse_q1(rng), 2, rng);

  const JointErrorModel m = JointErrorModel::fit(robot.nominal, fid, e, {}, robot.p_marker_m);
  bool found_joint1 = false;
  for (const JointPeriodicTerm& t : m.periodic_terms()) {
    if (t.joint != 0) continue;
    found_joint1 = true;
    EXPECT_NEAR(2.0 * std::numbers::pi / t.omega_per_rad, robot.period1_rad,
                0.005 * robot.period1_rad);
  }
  EXPECT_TRUE(found_joint1);
  // What is left at new angles is the noise's share of the fit: sigma sqrt(rank / J) at the
  // average leverage (~5 um here; the wave is 0.2 mm), up to twice that between the columns.
  const double with_terms = rms_prediction_error_m(m, robot, tgt);
  EXPECT_LT(with_terms, 2.0 * kSigma * std::sqrt(m.rank() / static_cast<double>(fid.size())));

  JointErrorModelOptions no_terms;
  no_terms.max_periodic_terms = 0;
  const JointErrorModel legendre =
      JointErrorModel::fit(robot.nominal, fid, e, no_terms, robot.p_marker_m);
  EXPECT_TRUE(legendre.periodic_terms().empty());
  EXPECT_GT(rms_prediction_error_m(legendre, robot, tgt), 10.0 * with_terms)
      << "Legendre degrees " << ::testing::PrintToString(legendre.joint_degrees());

  // Cross-validation keeps the terms found on all fiducials and refits their amplitudes.
  const double cv = joint_error_cv_rms_m(robot.nominal, fid, e, {}, robot.p_marker_m);
  EXPECT_LT(cv, 2.0 * std::sqrt(3.0) * kSigma);
}

TEST(JointErrorPeriodic, NoTermFromNoiseAlone) {
  CyclicRobot robot;
  robot.amplitude1_rad = 0.0;
  robot.amplitude3_rad = 0.0;
  Random rng(33);
  std::vector<double> q1;
  for (int k = 0; k < 40; ++k) q1.push_back(kCentre(0) + rng.uniform(-0.3, 0.3));
  const std::vector<JointVector> fid = fiducials(q1, 10, rng);
  Points3 e = robot.errors_of(fid);
  for (Eigen::Index j = 0; j < e.cols(); ++j) e.col(j) += rng.normal3(20e-6);
  const JointErrorModel m = JointErrorModel::fit(robot.nominal, fid, e, {}, robot.p_marker_m);
  EXPECT_TRUE(m.periodic_terms().empty());
}

TEST(JointErrorPeriodic, GivenTermsAreFittedAsGivenAndBadOnesRefused) {
  const CyclicRobot robot;
  Random rng(35);
  const std::vector<JointVector> fid = fiducials(sparse_q1(rng), 12, rng);
  const Points3 e = robot.errors_of(fid);
  const std::vector<JointVector> tgt = fiducials(sparse_q1(rng), 2, rng);
  JointErrorModelOptions o;
  o.joint_degrees = {2, 6, 6, 6, 2, 0};
  o.periodic_terms = {{0, 2.0 * std::numbers::pi / robot.period1_rad},
                      {2, 2.0 * std::numbers::pi / robot.period3_rad}};
  const JointErrorModel m = JointErrorModel::fit(robot.nominal, fid, e, o, robot.p_marker_m);
  ASSERT_EQ(m.periodic_terms().size(), 2U);
  EXPECT_EQ(m.periodic_terms()[1].joint, 2);
  EXPECT_EQ(m.joint_degrees(), o.joint_degrees);
  // Noise-free and the true periods: only the model's second-order terms remain (~A^2 r).
  EXPECT_LT(rms_prediction_error_m(m, robot, tgt), 1e-6);

  JointErrorModelOptions bad = o;
  bad.periodic_terms[0].omega_per_rad = 0.0;
  EXPECT_THROW((void)JointErrorModel::fit(robot.nominal, fid, e, bad), InputError);
  bad.periodic_terms[0].omega_per_rad = std::nan("");
  EXPECT_THROW((void)JointErrorModel::fit(robot.nominal, fid, e, bad), InputError);
  bad = o;
  bad.periodic_terms[1].joint = 6;
  EXPECT_THROW((void)JointErrorModel::fit(robot.nominal, fid, e, bad), InputError);
  bad = o;
  bad.max_periodic_terms = 17;
  EXPECT_THROW((void)JointErrorModel::fit(robot.nominal, fid, e, bad), InputError);
}

}  // namespace
}  // namespace vrreg::kinematics
