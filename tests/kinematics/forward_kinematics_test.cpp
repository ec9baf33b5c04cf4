// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/forward_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainjnttojacsolver.hpp>
#include <kdl/frames.hpp>
#include <numbers>

#include "kinematics_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg::kinematics {
namespace {

using testing::pose_from;
using testing::random_joints;

KDL::Chain to_kdl(const SerialChain& chain) {
  KDL::Chain kdl;
  for (const DhRow& r : chain.rows()) {
    kdl.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ),
                                KDL::Frame::DH(r.a_m, r.alpha_rad, r.d_m, r.theta_offset_rad)));
  }
  return kdl;
}

Eigen::Isometry3d from_kdl(const KDL::Frame& f) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      t.linear()(i, j) = f.M(static_cast<unsigned>(i), static_cast<unsigned>(j));
    t.translation()(i) = f.p(static_cast<unsigned>(i));
  }
  return t;
}

class ForwardKinematicsVsKdl : public ::testing::TestWithParam<const char*> {};

TEST_P(ForwardKinematicsVsKdl, AgreesToPicometres) {
  const SerialChain chain = *robot_by_name(GetParam());
  const KDL::Chain kdl = to_kdl(chain);
  KDL::ChainFkSolverPos_recursive fk(kdl);
  Random rng(2024);
  const int n = ::vrreg::testing::sanitized() ? 2000 : 20000;
  double worst_m = 0.0, worst_rot = 0.0;
  for (int k = 0; k < n; ++k) {
    const JointVector q = random_joints(rng, chain);
    KDL::JntArray qk(static_cast<unsigned>(chain.n_joints()));
    qk.data = q;
    KDL::Frame f;
    ASSERT_GE(fk.JntToCart(qk, f), 0);
    const auto e = testing::pose_error(forward_kinematics(chain, q), from_kdl(f));
    worst_m = std::max(worst_m, e.position_m);
    worst_rot = std::max(worst_rot, e.rotation_rad);
  }
  EXPECT_LE(worst_m, 1e-12);
  EXPECT_LE(worst_rot, 1e-12);
}

TEST_P(ForwardKinematicsVsKdl, JacobianMatchesKdlAndFiniteDifferences) {
  const SerialChain chain = *robot_by_name(GetParam());
  const KDL::Chain kdl = to_kdl(chain);
  KDL::ChainJntToJacSolver jac_solver(kdl);
  Random rng(77);
  for (int k = 0; k < 200; ++k) {
    const JointVector q = random_joints(rng, chain);
    const Jacobian j = jacobian(chain, q);
    KDL::JntArray qk(static_cast<unsigned>(chain.n_joints()));
    qk.data = q;
    KDL::Jacobian jk(static_cast<unsigned>(chain.n_joints()));
    ASSERT_GE(jac_solver.JntToJac(qk, jk), 0);
    EXPECT_EIGEN_NEAR(j, jk.data, 1e-12);
    // Central differences: linear part from the position, angular part from R^T dR.
    const double h = 1e-6;
    const Eigen::Isometry3d t0 = forward_kinematics(chain, q);
    for (int i = 0; i < chain.n_joints(); ++i) {
      JointVector qp = q, qm = q;
      qp(i) += h;
      qm(i) -= h;
      const Eigen::Isometry3d tp = forward_kinematics(chain, qp);
      const Eigen::Isometry3d tm = forward_kinematics(chain, qm);
      const Eigen::Vector3d v = (tp.translation() - tm.translation()) / (2 * h);
      const Eigen::Matrix3d dr = (tp.linear() - tm.linear()) / (2 * h) * t0.linear().transpose();
      const Eigen::Vector3d w(dr(2, 1), dr(0, 2), dr(1, 0));
      EXPECT_EIGEN_NEAR((j.block<3, 1>(0, i)), v, 1e-8);
      EXPECT_EIGEN_NEAR((j.block<3, 1>(3, i)), w, 1e-8);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, ForwardKinematicsVsKdl,
                         ::testing::Values("ur3", "ur5", "ur10", "ur5e", "lwr4"));

TEST(ForwardKinematics, Ur5ZeroPoseIsStretchedAlongMinusX) {
  // q = 0: upper arm and forearm along -x0, wrist offsets d4 along -y0, d5 along -z?, d6 along -y.
  const SerialChain chain = ur5();
  const Eigen::Isometry3d t = forward_kinematics(chain, JointVector::Zero(6));
  EXPECT_EIGEN_NEAR(t.translation(),
                    Eigen::Vector3d(-0.425 - 0.39225, -0.10915 - 0.0823, 0.089159 - 0.09465),
                    1e-15);
}

TEST(ForwardKinematics, BaseAndToolTransformsCompose) {
  const SerialChain plain = lwr4();
  const Eigen::Isometry3d base = pose_from({0.1, -0.2, 0.3}, 0.1, -0.2, 0.3);
  const Eigen::Isometry3d tool = pose_from({0.0, 0.01, 0.05}, 0.0, 0.5, 0.0);
  const SerialChain chain = plain.with_base(base).with_tool(tool);
  Random rng(5);
  const JointVector q = random_joints(rng, chain);
  const Eigen::Isometry3d expected = base * forward_kinematics(plain, q) * tool;
  EXPECT_EIGEN_NEAR(forward_kinematics(chain, q).matrix(), expected.matrix(), 1e-15);
  EXPECT_EIGEN_NEAR(flange_in_dh0(chain, q).matrix(), forward_kinematics(plain, q).matrix(), 0.0);
  const auto frames = link_frames(chain, q);
  ASSERT_EQ(frames.size(), 8u);
  EXPECT_EIGEN_NEAR((frames.back() * tool).matrix(), expected.matrix(), 1e-15);
}

TEST(ForwardKinematics, RejectsWrongSizeAndNonFiniteJoints) {
  const SerialChain chain = ur5();
  EXPECT_THROW(forward_kinematics(chain, Eigen::VectorXd::Zero(5)), InputError);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6);
  q(3) = std::nan("");
  EXPECT_THROW(forward_kinematics(chain, q), InputError);
  q(3) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(jacobian(chain, q), InputError);
}

}  // namespace
}  // namespace vrreg::kinematics
