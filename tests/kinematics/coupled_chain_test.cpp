// SPDX-License-Identifier: Apache-2.0
// Chains whose rows follow others' joint variables (URDF mimic joints): FK is the uncoupled
// chain's at the rows' values; the Jacobian and the marker partials match central differences
// in the variables; limits, wrapping, the numeric IK and the joint-space error model work on the
// variables; bad couplings are refused naming the joint. Random chains, seeded.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "chain_test_support.hpp"
#include "kinematics_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/kinematics/marker_partials.hpp"
#include "vrreg/kinematics/numeric_ik.hpp"
#include "vrreg_test.hpp"

namespace vrreg::kinematics::coupled_test {
namespace {

using testing::random_joints;

constexpr double kPi = std::numbers::pi;

// A random arm of `n` rows: rows 0 and 1 two parallel slides (a lifting column), the rest
// revolute with random DH parameters.
SerialChain random_rows(Random& rng, int n) {
  std::vector<DhRow> rows;
  std::vector<JointLimits> limits;
  for (int i = 0; i < n; ++i) {
    DhRow r;
    r.a_m = rng.uniform(-0.4, 0.4);
    r.d_m = rng.uniform(-0.2, 0.2);
    r.alpha_rad = std::round(rng.uniform(-2.0, 2.0)) * kPi / 2 + rng.uniform(-0.1, 0.1);
    r.theta_offset_rad = rng.uniform(-1.0, 1.0);
    if (i < 2) {
      r.type = JointType::kPrismatic;
      r.alpha_rad = 0.0;
      r.a_m = 0.0;
      limits.push_back({-0.1, 0.5});
    } else {
      limits.push_back({-3.0, 3.0});
    }
    rows.push_back(r);
  }
  const Eigen::Isometry3d tool(Eigen::Translation3d(0.01, -0.02, 0.08));
  return SerialChain("random", rows, limits, Eigen::Isometry3d::Identity(), tool);
}

// Rows 0 and 1 follow one slide variable (0.5 and 0.5 with a 10 mm offset); row 3 follows row
// 2's variable twice over (a revolute pair); every other row is its own variable.
JointCouplings column_and_pair(const SerialChain& rows) {
  JointCouplings c;
  c.variables.push_back({"lift", JointType::kPrismatic, {0.0, 0.8}});
  c.rows.push_back({0, 0.5, 0.0});
  c.rows.push_back({0, 0.5, 0.01});
  for (int r = 2; r < rows.n_rows(); ++r) {
    if (r == 3) {
      c.rows.push_back({1, 2.0, 0.1});
      continue;
    }
    c.rows.push_back({static_cast<int>(c.variables.size()), 1.0, 0.0});
    c.variables.push_back({"j" + std::to_string(r), JointType::kRevolute, rows.limits()[r]});
  }
  return c;
}

TEST(CoupledChain, CountsLimitsAndWrapping) {
  Random rng(11);
  const SerialChain rows = random_rows(rng, 7);
  const SerialChain chain = rows.with_couplings(column_and_pair(rows));
  EXPECT_EQ(chain.n_rows(), 7);
  EXPECT_EQ(chain.n_joints(), 5);
  EXPECT_TRUE(chain.coupled());
  EXPECT_EQ(chain.family(), ChainFamily::kGeneric);
  EXPECT_TRUE(chain.prismatic(0));
  EXPECT_FALSE(chain.prismatic(1));
  // The lift's own range [0, 0.8] narrowed to the rows' [-0.1, 0.5]: q <= 1.0 and q <= 0.98.
  EXPECT_DOUBLE_EQ(chain.limit(0).lower_rad, 0.0);
  EXPECT_DOUBLE_EQ(chain.limit(0).upper_rad, 0.8);
  // Variable 1 drives row 2 (limits +-3) and row 3 = 2 q + 0.1 (limits +-3): q in [-1.55, 1.45].
  EXPECT_NEAR(chain.limit(1).lower_rad, -1.55, 1e-15);
  EXPECT_NEAR(chain.limit(1).upper_rad, 1.45, 1e-15);
  EXPECT_FALSE(chain.wraps(0));  // a slide
  EXPECT_TRUE(chain.wraps(1));   // two whole turns of row 3 per turn
  EXPECT_TRUE(chain.wraps(2));
  JointCouplings half = column_and_pair(rows);
  half.rows[3].multiplier = 0.5;
  EXPECT_FALSE(rows.with_couplings(half).wraps(1));  // half a turn of row 3 per turn
  // with_tool / with_base / with_name keep the couplings; uncoupled() drops them.
  EXPECT_EQ(chain.with_tool(Eigen::Isometry3d::Identity()).couplings(), chain.couplings());
  EXPECT_EQ(chain.with_name("x").n_joints(), 5);
  EXPECT_EQ(chain.uncoupled().n_joints(), 7);
  EXPECT_FALSE(chain.uncoupled().coupled());
  EXPECT_TRUE(chain.within_limits(Eigen::VectorXd::Zero(5)));
  Eigen::VectorXd q = Eigen::VectorXd::Zero(5);
  q(1) = 1.5;  // row 3 at 3.1: beyond its limit
  EXPECT_FALSE(chain.within_limits(q));
}

TEST(CoupledChain, ForwardKinematicsIsTheUncoupledChainsAtTheRowValues) {
  Random rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const SerialChain rows = random_rows(rng, 6 + trial % 5);
    const SerialChain chain = rows.with_couplings(column_and_pair(rows));
    const JointVector q = random_joints(rng, chain);
    // The rows' values set by hand, independently of row_values.
    JointVector by_hand(rows.n_rows());
    by_hand(0) = 0.5 * q(0);
    by_hand(1) = 0.5 * q(0) + 0.01;
    by_hand(2) = q(1);
    by_hand(3) = 2.0 * q(1) + 0.1;
    for (int r = 4; r < rows.n_rows(); ++r) by_hand(r) = q(r - 2);
    EXPECT_EIGEN_NEAR(forward_kinematics(chain, q).matrix(),
                      forward_kinematics(rows, by_hand).matrix(), 1e-12);
    EXPECT_EIGEN_NEAR(chain.row_values(q), by_hand, 1e-15);
    const std::vector<Eigen::Isometry3d> frames = link_frames(chain, q);
    EXPECT_EQ(frames.size(), static_cast<std::size_t>(rows.n_rows()) + 1);
  }
}

TEST(CoupledChain, JacobianAndMarkerPartialsMatchCentralDifferences) {
  Random rng(13);
  const double h = 1e-6;
  for (int trial = 0; trial < 10; ++trial) {
    const SerialChain rows = random_rows(rng, 8);
    const SerialChain chain = rows.with_couplings(column_and_pair(rows));
    const JointVector q = random_joints(rng, chain);
    const Jacobian j = jacobian(chain, q);
    ASSERT_EQ(j.cols(), chain.n_joints());
    const Eigen::Vector3d marker(0.02, 0.01, 0.1);
    const MarkerPartials d = marker_partials(chain, q, marker);
    ASSERT_EQ(d.d_joint.cols(), chain.n_joints());
    ASSERT_EQ(d.d_a.cols(), chain.n_rows());
    EXPECT_EIGEN_NEAR(Eigen::MatrixXd(j), vrreg::testing::central_difference_jacobian(chain, q, h),
                      1e-8);
    for (int i = 0; i < chain.n_joints(); ++i) {
      JointVector qp = q, qm = q;
      qp(i) += h;
      qm(i) -= h;
      const Eigen::Vector3d mp = testing::marker_at(chain, qp, marker);
      const Eigen::Vector3d mm = testing::marker_at(chain, qm, marker);
      EXPECT_EIGEN_NEAR(d.d_joint.col(i), (mp - mm) / (2 * h), 1e-8) << "joint " << i;
    }
    EXPECT_EIGEN_NEAR(d.position_m, testing::marker_at(chain, q, marker), 1e-15);
  }
}

TEST(CoupledChain, NumericIkRoundTripsOnTheVariables) {
  Random rng(14);
  const SerialChain rows = random_rows(rng, 8);
  const SerialChain chain = rows.with_couplings(column_and_pair(rows));
  for (int trial = 0; trial < 5; ++trial) {
    const JointVector q = random_joints(rng, chain);
    const Eigen::Isometry3d target = forward_kinematics(chain, q);
    NumericIkOptions options;
    options.seed = 100 + static_cast<std::uint64_t>(trial);
    options.max_solutions = 1;
    const JointVector start = q + JointVector::Constant(q.size(), 0.05);
    const IkResult r = numeric_inverse_kinematics(chain, target, options, start);
    ASSERT_TRUE(r.ok()) << r.message;
    for (const IkSolution& s : r.solutions) {
      ASSERT_EQ(s.q_rad.size(), chain.n_joints());
      EXPECT_TRUE(chain.within_limits(s.q_rad));
      const testing::PoseError e = testing::pose_error(forward_kinematics(chain, s.q_rad), target);
      EXPECT_LT(e.position_m, 1e-9);
      EXPECT_LT(e.rotation_rad, 1e-9);
    }
  }
}

TEST(CoupledChain, DistancesAndShiftsLeaveNonWrappingJointsAlone) {
  Random rng(15);
  const SerialChain rows = random_rows(rng, 7);
  JointCouplings half = column_and_pair(rows);
  half.rows[3].multiplier = 0.5;
  const SerialChain chain = rows.with_couplings(half);
  const JointKinds kinds(chain);
  EXPECT_DOUBLE_EQ(kinds.difference(1, 2 * kPi, 0.0), 2 * kPi);  // not a whole turn of row 3
  EXPECT_NEAR(kinds.difference(2, 2 * kPi, 0.0), 0.0, 1e-15);
  JointVector q = JointVector::Zero(chain.n_joints());
  q(2) = 2 * kPi + 0.1;
  const std::optional<JointVector> in = shift_into_limits(chain, q);
  ASSERT_TRUE(in.has_value());
  EXPECT_NEAR((*in)(2), 0.1, 1e-12);
}

TEST(CoupledChain, RefusesBadCouplingsNamingTheJoint) {
  Random rng(16);
  const SerialChain rows = random_rows(rng, 6);
  const auto refused = [&](JointCouplings c, const std::string& expected) {
    try {
      (void)rows.with_couplings(std::move(c));
      ADD_FAILURE() << "accepted, expected: " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  };
  JointCouplings c = column_and_pair(rows);
  c.rows[1].multiplier = 0.0;
  refused(c, "follows joint 'lift' with multiplier 0");
  c = column_and_pair(rows);
  c.rows[1].multiplier = std::numeric_limits<double>::quiet_NaN();
  refused(c, "joint 'lift'");
  c = column_and_pair(rows);
  c.rows[1].offset = std::numeric_limits<double>::infinity();
  refused(c, "joint 'lift'");
  c = column_and_pair(rows);
  c.rows[2].variable = 9;
  refused(c, "DH row 3 follows joint variable 10");
  c = column_and_pair(rows);
  c.variables.push_back({"spare", JointType::kRevolute, {}});
  refused(c, "no DH row follows joint 'spare'");
  c = column_and_pair(rows);
  c.variables[0].limits = {1.0, 1.5};  // the rows reach 0.5 at q = 1.0 and 0.98
  refused(c, "the limits of joint 'lift' and of the joints that follow it leave no common range");
  c = column_and_pair(rows);
  c.rows.pop_back();
  refused(c, "couplings for 6 DH rows");
}

// The joint-space model of a coupled chain is the model of its physical joints: fitted on the
// variables, it predicts what the uncoupled chain's model fitted on the rows' values predicts.
TEST(CoupledChain, JointErrorModelIsThePhysicalJointsModel) {
  if (vrreg::testing::sanitized()) GTEST_SKIP() << "fits two models with degree selection";
  Random rng(17);
  const SerialChain rows = random_rows(rng, 7);
  const SerialChain chain = rows.with_couplings(column_and_pair(rows));
  std::vector<JointVector> q, q_rows;
  Points3 e(3, 120);
  for (int j = 0; j < 120; ++j) {
    q.push_back(random_joints(rng, chain));
    q_rows.push_back(chain.row_values(q.back()));
    // A smooth error of the physical joints: offsets of rows 1 and 3 and a slide scale error.
    JointVector actual = q_rows.back();
    actual(1) += 0.3e-3 + 2e-3 * actual(1);
    actual(3) += 1e-3;
    e.col(j) = forward_kinematics(rows, actual).translation() -
               forward_kinematics(rows, q_rows.back()).translation() + rng.normal3(1e-6);
  }
  JointErrorModelOptions options;
  options.max_joint_degree = 3;
  options.max_periodic_terms = 0;
  const JointErrorModel coupled = JointErrorModel::fit(chain, q, e, options);
  const JointErrorModel physical = JointErrorModel::fit(rows, q_rows, e, options);
  EXPECT_EQ(coupled.n_joints(), chain.n_joints());
  EXPECT_EQ(coupled.joint_degrees().size(), static_cast<std::size_t>(rows.n_rows()));
  EXPECT_EQ(coupled.joint_degrees(), physical.joint_degrees());
  EXPECT_LT(coupled.residual_rms_m(), 3e-6);
  for (int t = 0; t < 20; ++t) {
    const JointVector qt = random_joints(rng, chain);
    EXPECT_EIGEN_NEAR(coupled.predict_m(qt), physical.predict_m(chain.row_values(qt)), 1e-15);
    EXPECT_EIGEN_NEAR(coupled.joint_angle_errors_rad(qt),
                      physical.joint_angle_errors_rad(chain.row_values(qt)), 1e-15);
  }
  // Saved and restored on the coupled chain, it predicts the same.
  const JointErrorModel restored = JointErrorModel::restore(chain, coupled.saved());
  const JointVector qt = random_joints(rng, chain);
  EXPECT_EIGEN_NEAR(restored.predict_m(qt), coupled.predict_m(qt), 0.0);
  // The fitted ranges as the variables' values: each row's range mapped back.
  const auto [lo, hi] = coupled.joint_range_rad();
  ASSERT_EQ(lo.size(), chain.n_joints());
  double q0_lo = 1e9, q0_hi = -1e9;
  for (const JointVector& v : q) {
    q0_lo = std::min(q0_lo, v(0));
    q0_hi = std::max(q0_hi, v(0));
  }
  EXPECT_NEAR(lo(0), q0_lo, 1e-15);
  EXPECT_NEAR(hi(0), q0_hi, 1e-15);
  EXPECT_NEAR(joint_error_cv_rms_m(chain, q, e, options),
              joint_error_cv_rms_m(rows, q_rows, e, options), 1e-18);
}

}  // namespace
}  // namespace vrreg::kinematics::coupled_test
