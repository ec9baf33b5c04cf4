// SPDX-License-Identifier: Apache-2.0
// Joint-by-joint chains as DH chains: FK, the Jacobian (against central differences) and the
// recognised families, on random chains with revolute and prismatic joints.
#include "vrreg/kinematics/joint_chain.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "kinematics_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg::kinematics {
namespace {

using testing::pose_error;
using testing::random_joints;

// A random chain: random origins (some joints on parallel or intersecting axes), axes along a
// random direction or a coordinate axis, every third joint prismatic.
std::vector<ChainJoint> random_joint_list(Random& rng, int n) {
  std::vector<ChainJoint> joints;
  for (int i = 0; i < n; ++i) {
    ChainJoint j;
    j.name = "j" + std::to_string(i + 1);
    j.type = i % 3 == 2 ? JointType::kPrismatic : JointType::kRevolute;
    j.T_parent_joint = Eigen::Isometry3d::Identity();
    const int kind = static_cast<int>(rng.below(4));
    if (kind > 0) j.T_parent_joint.linear() = rng.rotation();
    if (kind != 1) j.T_parent_joint.translation() = rng.normal3(0.2);
    j.axis = kind == 3 ? Eigen::Vector3d(rng.normal3(1.0)) : Eigen::Vector3d::UnitZ();
    if (j.type == JointType::kPrismatic) j.limits = {-0.5, 0.8};
    joints.push_back(j);
  }
  return joints;
}

TEST(JointChain, FkAndJacobianOfRandomChainsMatchTheJointComposition) {
  Random rng(3);
  double worst = 0.0, worst_jacobian = 0.0;
  for (int c = 0; c < 200; ++c) {
    const int n = 1 + static_cast<int>(rng.below(kMaxJoints));
    const std::vector<ChainJoint> joints = random_joint_list(rng, n);
    Eigen::Isometry3d tip = Eigen::Isometry3d::Identity();
    tip.linear() = rng.rotation();
    tip.translation() = rng.normal3(0.1);
    const SerialChain chain = chain_from_joints("random", joints, tip);
    for (int k = 0; k < 20; ++k) {
      const JointVector q = random_joints(rng, chain);
      const Eigen::Isometry3d t = forward_kinematics(chain, q);
      const auto e = pose_error(t, joints_forward_kinematics(joints, tip, q));
      worst = std::max({worst, e.position_m, e.rotation_rad});
      // Central differences of FK: position exactly, rotation as the axis of R(+h) R(-h)^T.
      const Jacobian j = jacobian(chain, q);
      const double h = 1e-6;
      for (int i = 0; i < n; ++i) {
        JointVector qp = q, qm = q;
        qp(i) += h;
        qm(i) -= h;
        const Eigen::Isometry3d tp = forward_kinematics(chain, qp);
        const Eigen::Isometry3d tm = forward_kinematics(chain, qm);
        const Eigen::AngleAxisd w(Eigen::Matrix3d(tp.linear() * tm.linear().transpose()));
        Eigen::Matrix<double, 6, 1> fd;
        fd << (tp.translation() - tm.translation()) / (2 * h), w.angle() * w.axis() / (2 * h);
        worst_jacobian = std::max(worst_jacobian, (j.col(i) - fd).cwiseAbs().maxCoeff());
      }
    }
  }
  EXPECT_LE(worst, 1e-12);
  EXPECT_LE(worst_jacobian, 1e-8);
}

TEST(JointChain, BuiltLikeAUrItIsAUr) {
  // The UR5's DH rows as URDF origins: joint k's origin is row k-1's fixed part.
  const SerialChain ur = ur5();
  std::vector<ChainJoint> joints;
  for (int i = 0; i < 6; ++i) {
    ChainJoint j;
    if (i > 0) {
      const DhRow& r = ur.row(i - 1);
      j.T_parent_joint = Eigen::Translation3d(r.a_m, 0, r.d_m) *
                         Eigen::AngleAxisd(r.alpha_rad, Eigen::Vector3d::UnitX());
    }
    joints.push_back(j);
  }
  const Eigen::Isometry3d tip(Eigen::Translation3d(0, 0, ur.row(5).d_m));
  const SerialChain chain = chain_from_joints("ur5-joints", joints, tip);
  EXPECT_EQ(chain.family(), ChainFamily::kUr);
  EXPECT_TRUE(chain.tcp_is_flange_in_dh0());
  Random rng(4);
  for (int k = 0; k < 100; ++k) {
    const JointVector q = random_joints(rng, ur);
    EXPECT_LE(pose_error(forward_kinematics(chain, q), forward_kinematics(ur, q)).position_m,
              1e-15);
  }
}

TEST(JointChain, BadJointsThrow) {
  std::vector<ChainJoint> joints(1);
  joints[0].axis = Eigen::Vector3d::Zero();
  EXPECT_THROW(chain_from_joints("r", joints), InputError);
  EXPECT_THROW(chain_from_joints("r", {}), InputError);
  joints[0].axis = Eigen::Vector3d::UnitX();
  joints[0].limits = {1.0, -1.0};
  EXPECT_THROW(chain_from_joints("r", joints), InputError);
}

}  // namespace
}  // namespace vrreg::kinematics
