// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/kinematics/ur_ik.hpp"

namespace vrreg::kinematics {
namespace {

using units::kPi;

TEST(ConfigurationLabel, StringsAndIndicesAreStableAndRoundTrip) {
  EXPECT_EQ(ConfigurationLabel::ur(true, true, false).to_string(),
            "shoulder-left/elbow-up/wrist-noflip");
  EXPECT_EQ(ConfigurationLabel::ur(true, true, false).index(), 0);
  EXPECT_EQ(ConfigurationLabel::ur(false, false, true).to_string(),
            "shoulder-right/elbow-down/wrist-flip");
  EXPECT_EQ(ConfigurationLabel::ur(false, false, true).index(), 7);
  EXPECT_EQ(ConfigurationLabel::lwr(1, -1, 1).to_string(), "GC=+,-,+");
  EXPECT_EQ(ConfigurationLabel::lwr(1, -1, 1).index(), 2);
  EXPECT_EQ(ConfigurationLabel::lwr(-1, 1, 1).lwr_sign(2), -1);
  std::set<std::string> names;
  for (ArmKind kind : {ArmKind::kUr, ArmKind::kLwr}) {
    for (int i = 0; i < 8; ++i) {
      const ConfigurationLabel label(kind, i);
      names.insert(label.to_string());
      EXPECT_EQ(ConfigurationLabel::parse(label.to_string()), label);
    }
  }
  EXPECT_EQ(names.size(), 16u);
  EXPECT_THROW(ConfigurationLabel::parse("elbow-up"), InputError);
  EXPECT_THROW(ConfigurationLabel(ArmKind::kUr, 8), InputError);
}

TEST(ConfigurationLabel, UrZeroPoseIsShoulderLeft) {
  JointVector q(6);
  q << 0.0, -0.5, 1.0, 0.0, 1.0, 0.0;
  EXPECT_TRUE(ur_configuration(ur5(), q).shoulder_left());
  EXPECT_FALSE(ur_configuration(ur5(), q).wrist_flipped());
  q(4) = -1.0;
  EXPECT_TRUE(ur_configuration(ur5(), q).wrist_flipped());
  EXPECT_EQ(configuration_of(lwr4(), Eigen::VectorXd::Zero(7))->to_string(), "GC=+,+,+");
}

TEST(JointDistance, WrapsAngles) {
  Eigen::VectorXd a(3), b(3);
  a << kPi - 0.1, 0.0, 2 * kPi;
  b << -kPi + 0.1, 0.3, 0.0;
  EXPECT_NEAR(joint_distance_linf(a, b), 0.3, 1e-12);
  EXPECT_NEAR(joint_distance_l2(a, b), std::sqrt(0.2 * 0.2 + 0.3 * 0.3), 1e-12);
  EXPECT_NEAR(joint_distance(a, b, JointNorm::kL2), joint_distance_l2(a, b), 0.0);
  EXPECT_THROW(joint_distance_l2(a, Eigen::VectorXd::Zero(2)), InputError);
  EXPECT_NEAR(wrap_angle(kPi), kPi, 0.0);
  EXPECT_NEAR(wrap_angle(-kPi), kPi, 0.0);
  EXPECT_NEAR(wrap_angle(3 * kPi + 0.5), -kPi + 0.5, 1e-12);
}

TEST(JointDistance, NearestAndOrderDependOnTheNorm) {
  // L2 prefers one joint jumping by ~pi; Linf prefers small moves in every joint.
  Eigen::MatrixXd candidates(3, 2);
  candidates << 2.8, 1.0,  //
      0.0, 1.0,            //
      0.0, 1.0;
  const Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  EXPECT_EQ(*nearest_configuration(candidates, reference, JointNorm::kL2), 1);
  EXPECT_EQ(*nearest_configuration(candidates, reference, JointNorm::kLinf), 1);
  candidates(0, 0) = 1.5;
  EXPECT_EQ(*nearest_configuration(candidates, reference, JointNorm::kL2), 0);
  EXPECT_EQ(*nearest_configuration(candidates, reference, JointNorm::kLinf), 1);
  EXPECT_EQ(order_by_distance(candidates, reference, JointNorm::kL2), (std::vector<int>{0, 1}));
  EXPECT_FALSE(nearest_configuration(Eigen::MatrixXd(3, 0), reference, JointNorm::kL2));
}

// A gantry's 8 m carriage then two revolute joints: the carriage's travel is metres, not an angle
// (wrapped, 6.4 m - 0.1 m would be 0.017 "rad" and the far carriage position the nearest).
TEST(JointDistance, SlidesAreNotWrapped) {
  DhRow slide;
  slide.type = JointType::kPrismatic;
  DhRow turn;
  turn.a_m = 0.5;
  const SerialChain gantry("gantry", {slide, turn, turn}, {{0.0, 8.0}, {-kPi, kPi}, {-kPi, kPi}});
  const JointKinds kinds(gantry);
  Eigen::Vector3d a(0.1, kPi - 0.1, 0.0), b(6.4, -kPi + 0.1, 0.0);
  EXPECT_NEAR(joint_distance_linf(a, b, kinds), 6.3, 1e-12);
  EXPECT_NEAR(joint_distance_l2(a, b, kinds), std::sqrt(6.3 * 6.3 + 0.2 * 0.2), 1e-12);
  EXPECT_NEAR(joint_distance_linf(a, b), 0.2, 1e-12);  // as an angle the 6.3 m wraps to 0.017
  EXPECT_NEAR(kinds.difference(1, a(1), b(1)), -0.2, 1e-12);
  Eigen::MatrixXd candidates(3, 2);
  candidates.col(0) = b;
  candidates.col(1) = Eigen::Vector3d(0.6, kPi - 0.1, 0.0);
  EXPECT_EQ(*nearest_configuration(candidates, a, JointNorm::kL2, kinds), 1);
  EXPECT_EQ(*nearest_configuration(candidates, a, JointNorm::kL2), 0);
  EXPECT_EQ(order_by_distance(candidates, a, JointNorm::kLinf, kinds), (std::vector<int>{1, 0}));
}

TEST(JointDistance, ShiftsIntoLimits) {
  const SerialChain chain = ur5();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6);
  q(0) = 3.0;
  Eigen::VectorXd reference = Eigen::VectorXd::Zero(6);
  reference(0) = -3.5;
  const auto shifted = shift_nearest(chain, q, reference);
  ASSERT_TRUE(shifted);
  EXPECT_NEAR((*shifted)(0), 3.0 - 2 * kPi, 1e-15);
  q(0) = 7.0;  // outside +-2 pi, its shift 7 - 2 pi is inside
  EXPECT_NEAR((*shift_into_limits(chain, q))(0), 7.0 - 2 * kPi, 1e-15);
  const SerialChain lwr = lwr4();
  Eigen::VectorXd ql = Eigen::VectorXd::Zero(7);
  ql(1) = 2.5;  // 143 deg: no shift fits +-120 deg
  EXPECT_FALSE(shift_into_limits(lwr, ql));
}

TEST(InverseKinematics, DispatchesByFamily) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() << 0.3, 0.2, 0.4;
  EXPECT_NO_THROW(inverse_kinematics(ur5(), t));
  EXPECT_NO_THROW(inverse_kinematics(lwr4(), t));  // the arm angle free
  EXPECT_NO_THROW(inverse_kinematics(lwr4(), t, 0.3));
  std::vector<DhRow> rows = ur5().rows();
  rows[0].a_m = 0.05;
  const SerialChain generic("generic", rows, ur5().limits());
  // A generic chain gets the numerical IK, and labels from the signs of its branch joints.
  JointVector q(6);
  q << 0.3, -1.1, 1.2, -0.7, 0.9, 0.2;
  const IkResult r = inverse_kinematics(generic, forward_kinematics(generic, q));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.solutions.front().config.kind(), ArmKind::kGeneric);
  EXPECT_EQ(configuration_of(generic, q)->to_string(), "q3+,q5+");
}

TEST(ConfigurationLabel, GenericLabelsPrintAndParse) {
  const ConfigurationLabel l = ConfigurationLabel::generic(0b10100, 0b10000);
  EXPECT_EQ(l.to_string(), "q3+,q5-");
  EXPECT_EQ(l.index(), 2);
  EXPECT_EQ(ConfigurationLabel::parse("q3+,q5-"), l);
  EXPECT_EQ(ConfigurationLabel::parse("single-class"), ConfigurationLabel::generic(0, 0));
  for (const char* bad : {"q3+,", "q0+", "q3", "q3+,q3-", "q17+", "x3+"}) {
    EXPECT_THROW(ConfigurationLabel::parse(bad), InputError) << bad;
  }
}

}  // namespace
}  // namespace vrreg::kinematics
