// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/lwr_ik.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kinematics_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg::kinematics {
namespace {

using testing::pose_error;
using testing::pose_from;
using testing::random_joints;
using units::kPi;

bool generic(const JointVector& q) {
  return std::abs(std::sin(q(1))) > 1e-3 && std::abs(std::sin(q(3))) > 1e-3 &&
         std::abs(std::sin(q(5))) > 1e-3;
}

TEST(LwrIk, EveryConfigurationMapsBackAndTheIkIsComplete) {
  const SerialChain chain = lwr4();
  IkOptions all;  // every configuration, limits off, to test the flips as well
  all.apply_joint_limits = false;
  Random rng(99);
  const int n = ::vrreg::testing::sanitized() ? 20000 : 100000;
  long tested = 0, found = 0, solutions = 0, arm_state_ok = 0;
  double worst_m = 0.0, worst_rad = 0.0;
  for (int k = 0; k < n; ++k) {
    const JointVector q = random_joints(rng, chain);
    const LwrArmState state = lwr_arm_state(chain, q);
    const Eigen::Isometry3d& t = state.T_base_tcp;
    EXPECT_LE(pose_error(t, forward_kinematics(chain, q)).position_m, 0.0);
    const IkResult r = lwr_inverse_kinematics(chain, t, state.psi_rad, all);
    ASSERT_TRUE(r.ok()) << r.message;
    bool contains = false;
    for (const IkSolution& s : r.solutions) {
      ++solutions;
      const auto e = pose_error(forward_kinematics(chain, s.q_rad), t);
      worst_m = std::max(worst_m, e.position_m);
      worst_rad = std::max(worst_rad, e.rotation_rad);
      EXPECT_EQ(lwr_configuration(chain, s.q_rad), s.config);
      contains = contains || joint_distance_linf(s.q_rad, q) < 1e-7;
      // All eight share the arm angle (the same elbow point).
      if (generic(s.q_rad)) {
        const double psi = lwr_arm_state(chain, s.q_rad).psi_rad;
        if (std::abs(wrap_angle(psi - state.psi_rad)) < 1e-7) ++arm_state_ok;
      } else {
        ++arm_state_ok;
      }
    }
    if (generic(q)) {
      ++tested;
      if (contains) ++found;
      EXPECT_EQ(r.solutions.size(), 8u);
    }
  }
  EXPECT_LE(worst_m, 1e-9);
  EXPECT_LE(worst_rad, 1e-9);
  EXPECT_GE(static_cast<double>(found) / static_cast<double>(tested), 0.9999);
  EXPECT_EQ(arm_state_ok, solutions);
  std::printf("[ lwr4 ] %d poses, %ld solutions, worst %.3g m %.3g rad, completeness %ld/%ld\n", n,
              solutions, worst_m, worst_rad, found, tested);
}

TEST(LwrIk, JointLimitsKeepOnlyFeasibleConfigurationsAndContainTheSample) {
  const SerialChain chain = lwr4();
  Random rng(5);
  const int n = ::vrreg::testing::sanitized() ? 5000 : 50000;
  long tested = 0, found = 0;
  for (int k = 0; k < n; ++k) {
    const JointVector q = random_joints(rng, chain);
    const LwrArmState state = lwr_arm_state(chain, q);
    const IkResult r = lwr_inverse_kinematics(chain, state.T_base_tcp, state.psi_rad);
    ASSERT_TRUE(r.ok());
    IkOptions unlimited;
    unlimited.apply_joint_limits = false;
    const IkResult all = lwr_inverse_kinematics(chain, state.T_base_tcp, state.psi_rad, unlimited);
    EXPECT_EQ(r.solutions.size() + static_cast<std::size_t>(r.n_outside_limits),
              all.solutions.size());
    bool contains = false;
    for (const IkSolution& s : r.solutions) {
      EXPECT_TRUE(chain.within_limits(s.q_rad));
      contains = contains || joint_distance_linf(s.q_rad, q) < 1e-7;
    }
    if (generic(q)) {
      ++tested;
      found += contains ? 1 : 0;
    }
  }
  EXPECT_GE(static_cast<double>(found) / static_cast<double>(tested), 0.9999);
}

TEST(LwrIk, ArmAngleRotatesTheElbowAboutTheShoulderWristAxis) {
  const SerialChain chain = lwr4();
  const Eigen::Isometry3d t = pose_from({0.45, 0.1, 0.5}, kPi, 0.3, 0.2);
  IkOptions all;
  all.apply_joint_limits = false;
  Eigen::Vector3d previous_elbow = Eigen::Vector3d::Zero();
  for (double psi = -3.0; psi <= 3.0; psi += 0.5) {
    const IkResult r = lwr_inverse_kinematics(chain, t, psi, all);
    ASSERT_EQ(r.solutions.size(), 8u);
    const Eigen::Vector3d elbow = link_frames(chain, r.solutions[0].q_rad)[3].translation();
    for (const IkSolution& s : r.solutions) {
      EXPECT_EIGEN_NEAR(link_frames(chain, s.q_rad)[3].translation(), elbow, 1e-12);
      EXPECT_NEAR(wrap_angle(lwr_arm_state(chain, s.q_rad).psi_rad - psi), 0.0, 1e-12);
    }
    if (psi > -3.0) {
      EXPECT_GT((elbow - previous_elbow).norm(), 1e-3);
    }
    previous_elbow = elbow;
  }
}

TEST(LwrIk, FlipRulesOfTheDesign) {
  const SerialChain chain = lwr4();
  IkOptions all;
  all.apply_joint_limits = false;
  const IkResult r =
      lwr_inverse_kinematics(chain, pose_from({0.3, -0.3, 0.6}, 0.2, 2.0, 1.0), 0.4, all);
  ASSERT_EQ(r.solutions.size(), 8u);
  const JointVector& base = r.solutions[0].q_rad;
  const JointVector& flip2 = r.solutions[4].q_rad;  // GC=-,+,+
  EXPECT_EQ(r.solutions[4].config.to_string(), "GC=-,+,+");
  EXPECT_NEAR(wrap_angle(flip2(0) - base(0) - kPi), 0.0, 1e-12);
  EXPECT_NEAR(flip2(1), -base(1), 1e-12);
  EXPECT_NEAR(wrap_angle(flip2(2) - base(2) - kPi), 0.0, 1e-12);
  for (int i = 3; i < 7; ++i) EXPECT_NEAR(flip2(i), base(i), 1e-12);
  EXPECT_GT(base(1), 0.0);
  EXPECT_GT(base(3), 0.0);
  EXPECT_GT(base(5), 0.0);
}

TEST(LwrIk, SingularCasesAreFlagged) {
  const SerialChain chain = lwr4();
  JointVector q(7);
  q << 0.3, 0.5, -0.2, 0.0, 0.4, 0.6, 0.1;  // stretched elbow: psi undefined
  LwrArmState state = lwr_arm_state(chain, q);
  EXPECT_NE(state.singular & kElbowSingular, 0);
  IkResult r = lwr_inverse_kinematics(chain, state.T_base_tcp, 0.7);
  EXPECT_NE(r.singular & kElbowSingular, 0);
  for (const IkSolution& s : r.solutions) {
    EXPECT_LE(pose_error(forward_kinematics(chain, s.q_rad), state.T_base_tcp).position_m, 1e-9);
  }
  q << 0.3, 0.0, -0.2, 1.0, 0.4, 0.6, 0.1;  // theta2 = 0: joints 1 and 3 aligned
  state = lwr_arm_state(chain, q);
  EXPECT_NE(state.singular & kShoulderSingular, 0);
  IkOptions options;
  options.singular_free_angle_rad = 0.2;
  r = lwr_inverse_kinematics(chain, state.T_base_tcp, state.psi_rad, options);
  ASSERT_TRUE(r.ok());
  EXPECT_NE(r.singular & kShoulderSingular, 0);
  for (const IkSolution& s : r.solutions) {
    EXPECT_EQ(s.config.lwr_sign(2), 1);  // the theta2 pair collapses
    EXPECT_NEAR(wrap_angle(s.q_rad(2) - 0.2 - (s.config.lwr_sign(4) < 0 ? kPi : 0.0)), 0.0,
                1e-12);  // joint 3 takes the stated free value (+ pi for the theta4 flip)
    const auto e = pose_error(forward_kinematics(chain, s.q_rad), state.T_base_tcp);
    EXPECT_LE(e.position_m, 1e-9);
    EXPECT_LE(e.rotation_rad, 1e-9);
  }
  q << 0.3, 0.5, -0.2, 1.0, 0.4, 0.0, 0.1;  // theta6 = 0: joints 5 and 7 aligned
  state = lwr_arm_state(chain, q);
  r = lwr_inverse_kinematics(chain, state.T_base_tcp, state.psi_rad, options);
  EXPECT_NE(r.singular & kWristSingular, 0);
  EXPECT_EQ(r.solutions.size() + static_cast<std::size_t>(r.n_outside_limits), 4u);
  for (const IkSolution& s : r.solutions) {
    const auto e = pose_error(forward_kinematics(chain, s.q_rad), state.T_base_tcp);
    EXPECT_LE(e.position_m, 1e-9);
    EXPECT_LE(e.rotation_rad, 1e-9);
  }
  // Wrist straight above the shoulder: the reference plane of psi is undefined.
  Eigen::Isometry3d t = pose_from({0.0, 0.0, 0.0}, kPi, 0.0, 0.0);
  t.translation() = Eigen::Vector3d(0.0, 0.0, 0.31 + 0.6) + 0.078 * t.linear().col(2);
  r = lwr_inverse_kinematics(chain, t, 0.5);
  EXPECT_NE(r.singular & kArmAngleSingular, 0);
  for (const IkSolution& s : r.solutions) {
    EXPECT_LE(pose_error(forward_kinematics(chain, s.q_rad), t).position_m, 1e-9);
  }
}

TEST(LwrIk, CalibratedOffsetsToolAndBaseKeepTheIkExact) {
  std::vector<DhRow> rows = lwr4().rows();
  for (std::size_t i = 0; i < 7; ++i) rows[i].theta_offset_rad = 0.003 * static_cast<double>(i + 1);
  rows[0].d_m = 0.3105;
  rows[4].d_m = 0.3898;
  const SerialChain chain = SerialChain("lwr-cal", rows, lwr4().limits())
                                .with_tool(pose_from({0.01, -0.02, 0.06}, 0.1, 0.0, 0.2))
                                .with_base(pose_from({0.5, 0.2, 0.8}, kPi, 0.0, 0.3));
  ASSERT_EQ(chain.family(), ChainFamily::kLwr);
  Random rng(21);
  long tested = 0, found = 0;
  for (int k = 0; k < 5000; ++k) {
    const JointVector q = random_joints(rng, chain);
    const LwrArmState state = lwr_arm_state(chain, q);
    EXPECT_LE(pose_error(state.T_base_tcp, forward_kinematics(chain, q)).position_m, 1e-15);
    const IkResult r = lwr_inverse_kinematics(chain, state.T_base_tcp, state.psi_rad);
    bool contains = false;
    for (const IkSolution& s : r.solutions) {
      const auto e = pose_error(forward_kinematics(chain, s.q_rad), state.T_base_tcp);
      EXPECT_LE(e.position_m, 1e-9);
      EXPECT_LE(e.rotation_rad, 1e-9);
      contains = contains || joint_distance_linf(s.q_rad, q) < 1e-7;
    }
    if (generic(q)) {
      ++tested;
      found += contains ? 1 : 0;
    }
  }
  EXPECT_EQ(found, tested);
}

TEST(LwrIk, UnreachableAndBadInput) {
  const SerialChain chain = lwr4();
  const IkResult far = lwr_inverse_kinematics(chain, pose_from({1.2, 0.0, 0.3}, 0, 0, 0), 0.0);
  EXPECT_EQ(far.status, IkStatus::kUnreachable);
  EXPECT_TRUE(far.solutions.empty());
  EXPECT_NE(far.message.find("reach"), std::string::npos);
  EXPECT_THROW(lwr_inverse_kinematics(chain, pose_from({0.4, 0, 0.3}, 0, 0, 0), std::nan("")),
               InputError);
  EXPECT_THROW(lwr_inverse_kinematics(ur5(), pose_from({0.4, 0, 0.3}, 0, 0, 0), 0.0), InputError);
  EXPECT_THROW(lwr_arm_state(chain, Eigen::VectorXd::Zero(6)), InputError);
}

}  // namespace
}  // namespace vrreg::kinematics
