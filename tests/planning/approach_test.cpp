// SPDX-License-Identifier: Apache-2.0
// One approach direction per joint: a via point before every location, each joint of it on the
// chosen side of the location's by the offset (clamped into the limits, refused at a limit); off
// by default, the plan then as before; the robot program goes via -> location; the cost in joint
// path and movej time against a hand count.
#include "vrreg/planning/approach.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "planning_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/planning/monitor_points.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg/planning/robot_program.hpp"

namespace vrreg::planning::approach_test {
namespace {

using testing::ur5_with_sphere;

std::vector<PartPoint> two_parts() {
  return {{"hole_A", {0.42, -0.14, 0.25}}, {"hole_B", {0.48, -0.14, 0.25}}};
}

PlanOptions options(const Eigen::VectorXd& direction) {
  PlanOptions o;
  o.halfwidth_m = 0.010;
  o.spacing_m = 0.005;
  o.approach.direction = direction;
  return o;
}

Eigen::VectorXd signs(std::initializer_list<double> s) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(s.size()));
  Eigen::Index i = 0;
  for (const double x : s) v(i++) = x;
  return v;
}

TEST(Approach, EveryLocationGetsAViaPointOnTheChosenSideOfEveryJoint) {
  const kinematics::SerialChain chain = ur5_with_sphere();
  const Eigen::VectorXd direction = signs({1, -1, 1, 1, -1, 1});
  const PlanResult r = make_plan(chain, two_parts(), options(direction));
  ASSERT_TRUE(r.ok()) << r.message;
  const double offset = units::deg_to_rad(2.0);
  for (const PlannedLocation& l : r.locations) {
    ASSERT_TRUE(l.via_q_rad.has_value()) << l.point;
    // Each joint moves from the via point to the location by +offset in its direction.
    const Eigen::VectorXd step = (l.q_rad - *l.via_q_rad).cwiseProduct(direction);
    EXPECT_NEAR(step.minCoeff(), offset, 1e-12) << l.point;
    EXPECT_NEAR(step.maxCoeff(), offset, 1e-12) << l.point;
    EXPECT_LT(
        (kinematics::forward_kinematics(chain, *l.via_q_rad).translation() - l.via_robot_m).norm(),
        1e-12);
  }
}

TEST(Approach, OffByDefaultAndThePlanIsOtherwiseTheSame) {
  const kinematics::SerialChain chain = ur5_with_sphere();
  const PlanResult off = make_plan(chain, two_parts(), options(Eigen::VectorXd()));
  const PlanResult on = make_plan(chain, two_parts(), options(signs({1, 1, 1, 1, 1, 1})));
  ASSERT_TRUE(off.ok() && on.ok());
  ASSERT_EQ(off.locations.size(), on.locations.size());
  for (std::size_t i = 0; i < off.locations.size(); ++i) {
    EXPECT_FALSE(off.locations[i].via_q_rad.has_value());
    EXPECT_EQ(off.locations[i].point, on.locations[i].point);
    EXPECT_EQ(off.locations[i].q_rad, on.locations[i].q_rad);
  }
  EXPECT_EQ(off.within_cubes_m, on.within_cubes_m);
}

TEST(Approach, AJointAtItsLimitOnTheSideItComesFromIsRefused) {
  const kinematics::SerialChain chain = ur5_with_sphere();
  ApproachOptions a;
  a.direction = signs({1, 1, 1, 1, 1, 1});
  kinematics::JointVector q = kinematics::JointVector::Constant(6, 0.3);
  const double lower = chain.limit(2).lower_rad;
  // 0.75 of the offset from the limit: clamped to the limit, still 0.75 offset to travel.
  q(2) = lower + 0.75 * a.offset_rad;
  const kinematics::JointVector via = approach_via(chain, q, a);
  EXPECT_DOUBLE_EQ(via(2), lower);
  EXPECT_NEAR(via(0), 0.3 - a.offset_rad, 1e-15);
  // At 0.25 of the offset: less than kMinApproachFraction fits, refused naming the joint.
  q(2) = lower + 0.25 * a.offset_rad;
  try {
    (void)approach_via(chain, q, a);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("joint 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("limit"), std::string::npos) << e.what();
  }
  // Coming from the other side, the same location is fine.
  a.direction(2) = -1.0;
  EXPECT_NEAR(approach_via(chain, q, a)(2), q(2) + a.offset_rad, 1e-15);
}

TEST(Approach, BadOptionsAreRefused) {
  const kinematics::SerialChain chain = ur5_with_sphere();
  ApproachOptions a;
  a.direction = signs({1, 1, 1});
  EXPECT_THROW(a.validate(chain), InputError);
  a.direction = signs({1, 1, 0, 1, 1, 1});
  EXPECT_THROW(a.validate(chain), InputError);
  a.direction = signs({1, 1, 1, 1, 1, 1});
  a.offset_rad = 0.0;
  EXPECT_THROW(a.validate(chain), InputError);
  a.offset_rad = std::nan("");
  EXPECT_THROW(a.validate(chain), InputError);
}

TEST(Approach, TheProgramMovesViaThenLocationAndTheCostCountsBoth) {
  ProgramLocation first{"A", Role::kFiducial, "", kinematics::JointVector::Zero(6)};
  ProgramLocation second{"B", Role::kTarget, "", kinematics::JointVector::Constant(6, 0.5)};
  second.via_q_rad = kinematics::JointVector::Constant(6, 0.4);
  const std::string csv = robot_program({first, second}, ProgramFormat::kJointCsv);
  const auto via_row = csv.find("\n2,B,via,");
  const auto b_row = csv.find("\n3,B,target,");
  ASSERT_NE(via_row, std::string::npos) << csv;
  ASSERT_NE(b_row, std::string::npos) << csv;
  EXPECT_LT(via_row, b_row);
  EXPECT_NE(csv.find(",0.40000000000000002,", via_row), std::string::npos) << csv;
  EXPECT_EQ(csv.substr(b_row - 2, 2), ",0");  // the via row asks for no readings
  const std::string ur = robot_program({first, second}, ProgramFormat::kUrScript);
  const auto via_move = ur.find("movej([0.4, 0.4");
  const auto b_move = ur.find("movej([0.5, 0.5");
  ASSERT_NE(via_move, std::string::npos) << ur;
  ASSERT_NE(b_move, std::string::npos) << ur;
  EXPECT_LT(via_move, b_move);
  EXPECT_EQ(ur.find("popup", via_move) > b_move, true);  // no stop at the via point
  const std::string krl = robot_program({first, second}, ProgramFormat::kKrl);
  EXPECT_LT(krl.find("PTP {A1 22.918"), krl.find("PTP {A1 28.647")) << krl;

  // movej time (v 0.5, a 0.8: trapezoid above 0.3125 rad, else triangle 2 sqrt(d / a)):
  // 0 -> 0.4 trapezoid 0.4 / 0.5 + 0.5 / 0.8 = 1.425 s; 0.4 -> 0.5 triangle 2 sqrt(0.125) s.
  ProgramOptions o;
  const ProgramDuration d = program_duration({first, second}, o);
  EXPECT_NEAR(d.motion_s, 1.425 + 2.0 * std::sqrt(0.1 / 0.8), 1e-12);
  EXPECT_EQ(d.stops, 2);
}

TEST(Approach, CostOfAPlanAgainstAHandCount) {
  PlanResult plan;
  PlannedLocation a;
  a.point = "A";
  a.q_rad = kinematics::JointVector::Zero(6);
  a.via_q_rad = kinematics::JointVector::Constant(6, -0.1);
  PlannedLocation b = a;
  b.point = "B";
  b.q_rad = kinematics::JointVector::Constant(6, 1.0);
  b.via_q_rad = kinematics::JointVector::Constant(6, 0.9);
  plan.locations = {a, b};
  const ApproachCost c = approach_cost(plan, ProgramOptions{});
  EXPECT_EQ(c.n_via, 2);
  EXPECT_NEAR(c.joint_path_rad, 1.0, 1e-15);
  // via A -> A 0.1, A -> via B 0.9, via B -> B 0.1.
  EXPECT_NEAR(c.joint_path_with_vias_rad, 1.1, 1e-15);
  EXPECT_NEAR(c.motion_s, 1.0 / 0.5 + 0.5 / 0.8, 1e-12);
  const double triangle = 2.0 * std::sqrt(0.1 / 0.8);
  EXPECT_NEAR(c.motion_with_vias_s, triangle + 0.9 / 0.5 + 0.5 / 0.8 + triangle, 1e-12);
}

}  // namespace
}  // namespace vrreg::planning::approach_test
