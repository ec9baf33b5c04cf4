// SPDX-License-Identifier: Apache-2.0
// The joint model's orientation-only terms against closed forms: a constant small rotation of
// one link, in its own frame (what a wrist's twist error does, hardly seen by positions), and a
// joint-angle error linear in its joint are recovered, so predicted at new joints to rounding; a
// wrist joint's cyclic angle error (a transmission error, which only orientations show) is found
// by the periodogram at its frequency and predicted to 1e-9; saved terms that do not fit the arm
// are refused.
#include "correction/joint_rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "vrreg/core/file_error.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg::detail {
namespace {

Eigen::MatrixXd random_joints(Random& rng, int n_joints, int n) {
  Eigen::MatrixXd q(n_joints, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n_joints; ++i) q(i, j) = rng.uniform(-1.2, 1.2);
  return q;
}

TEST(JointRotation, ALinksConstantRotationIsRecoveredAndPredicted) {
  const kinematics::SerialChain ur5 = kinematics::ur5();
  Random rng(3);
  const Eigen::MatrixXd q = random_joints(rng, 6, 300);
  // Link 5 turned by r in its own frame, and joint 2's angle error 2 mrad per rad of travel.
  const Eigen::Vector3d r(1.5e-3, -2e-3, 5e-4);
  const auto g_of = [&](const Eigen::VectorXd& qj) {
    const std::vector<Eigen::Isometry3d> frames = kinematics::link_frames(ur5, qj);
    const kinematics::Jacobian J = kinematics::jacobian(ur5, qj);
    return Eigen::Vector3d(frames[5].linear() * r + J.block<3, 1>(3, 1) * 2e-3 * qj(1));
  };
  Points3 g(3, q.cols());
  for (Eigen::Index j = 0; j < q.cols(); ++j) g.col(j) = g_of(q.col(j));
  const JointRotationTerms terms = fit_joint_rotation(ur5, q, g).terms;
  EXPECT_GE(terms.degree, 1);
  ASSERT_EQ(terms.link_rotations_rad.size(), 18);
  const Eigen::MatrixXd q_new = random_joints(rng, 6, 50);
  for (Eigen::Index j = 0; j < q_new.cols(); ++j) {
    const Eigen::Vector3d expected = g_of(q_new.col(j));
    EXPECT_LT((joint_rotation_rad(terms, ur5, q_new.col(j)) - expected).norm(), 1e-13)
        << j;  // mrad-size terms, to rounding
  }
}

TEST(JointRotation, AWristJointsCyclicErrorIsFoundAndPredicted) {
  const kinematics::SerialChain ur5 = kinematics::ur5();
  Random rng(5);
  const Eigen::MatrixXd q = random_joints(rng, 6, 300);
  // Joint 5's transmission error, 0.4 mrad with a 20 deg period, and link 6 turned by r.
  const double omega_per_rad = 2.0 * M_PI / (20.0 * M_PI / 180.0);
  const Eigen::Vector3d r(-1e-3, 5e-4, 2e-3);
  const auto g_of = [&](const Eigen::VectorXd& qj) {
    const std::vector<Eigen::Isometry3d> frames = kinematics::link_frames(ur5, qj);
    const kinematics::Jacobian J = kinematics::jacobian(ur5, qj);
    return Eigen::Vector3d(frames[6].linear() * r +
                           J.block<3, 1>(3, 4) * 4e-4 * std::sin(omega_per_rad * qj(4) + 0.7));
  };
  Points3 g(3, q.cols());
  for (Eigen::Index j = 0; j < q.cols(); ++j) g.col(j) = g_of(q.col(j));
  const JointRotationTerms terms = fit_joint_rotation(ur5, q, g).terms;
  ASSERT_EQ(terms.periodic.size(), 1U);
  EXPECT_EQ(terms.periodic[0].joint, 4);
  EXPECT_NEAR(terms.periodic[0].omega_per_rad, omega_per_rad, 1e-9 * omega_per_rad);
  const Eigen::MatrixXd q_new = random_joints(rng, 6, 50);
  for (Eigen::Index j = 0; j < q_new.cols(); ++j) {
    EXPECT_LT((joint_rotation_rad(terms, ur5, q_new.col(j)) - g_of(q_new.col(j))).norm(), 1e-9)
        << j;
  }
}

TEST(JointRotation, NoTermsWhenThereIsNothingToFit) {
  const kinematics::SerialChain ur5 = kinematics::ur5();
  Random rng(4);
  const Eigen::MatrixXd q = random_joints(rng, 6, 100);
  Points3 noise(3, q.cols());
  for (Eigen::Index j = 0; j < q.cols(); ++j) noise.col(j) = rng.normal3(1e-4);
  const JointRotationTerms terms = fit_joint_rotation(ur5, q, noise).terms;
  EXPECT_EQ(terms.degree, -1);
  EXPECT_EQ(terms.link_rotations_rad.size(), 0);
  EXPECT_TRUE(terms.periodic.empty());  // noise has no peak above the false-alarm threshold
  // Only the constant fitted with the terms, the noise's mean: 1e-4 / sqrt(100) per axis.
  EXPECT_LT(joint_rotation_rad(terms, ur5, q.col(0)).norm(), 5e-5);
}

TEST(JointRotation, TermsThatDoNotFitTheArmAreRefused) {
  JointRotationTerms t;
  t.link_rotations_rad = Eigen::VectorXd::Zero(17);
  EXPECT_THROW(validate_joint_rotation(t, 6), InputError);
  t.link_rotations_rad = Eigen::VectorXd::Zero(18);
  EXPECT_NO_THROW(validate_joint_rotation(t, 6));
  t.coefficients = Eigen::VectorXd::Zero(6);
  EXPECT_THROW(validate_joint_rotation(t, 6), InputError);  // coefficients without a degree
  t.degree = 0;
  t.q_lo_rad = Eigen::VectorXd::Zero(6);
  t.q_hi_rad = Eigen::VectorXd::Ones(6);
  EXPECT_NO_THROW(validate_joint_rotation(t, 6));
  t.link_rotations_rad(3) = std::nan("");
  EXPECT_THROW(validate_joint_rotation(t, 6), InputError);
  t.link_rotations_rad(3) = 0.0;
  t.periodic = {{5, 18.0}};
  EXPECT_THROW(validate_joint_rotation(t, 6), InputError);  // no coefficients for the term
  t.periodic_coefficients = Eigen::VectorXd::Zero(2);
  EXPECT_NO_THROW(validate_joint_rotation(t, 6));
  t.periodic = {{6, 18.0}};
  EXPECT_THROW(validate_joint_rotation(t, 6), InputError);  // a seventh joint
  t.periodic = {{5, 0.0}};
  EXPECT_THROW(validate_joint_rotation(t, 6), InputError);  // no frequency
}

}  // namespace
}  // namespace vrreg::detail
