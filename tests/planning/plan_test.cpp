// SPDX-License-Identifier: Apache-2.0
// The whole of Procedure 1 on the UR5 and the LWR 4+: grid per cube, visiting order and the joints
// of every location (FK back to the position, nearest IK solution to the part point's joints).
#include "vrreg/planning/plan.hpp"

#include <map>
#include <set>

#include "planning_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg::planning {
namespace {

using kinematics::SerialChain;

using testing::ur5_with_sphere;

std::vector<PartPoint> four_parts() {
  return {{"hole_A", {0.42, -0.14, 0.25}},
          {"hole_B", {0.48, -0.14, 0.25}},
          {"pin_C", {0.48, -0.06, 0.26}},
          {"pin_D", {0.42, -0.06, 0.24}}};
}

PlanOptions options_10_5() {
  PlanOptions o;
  o.halfwidth_m = 0.010;
  o.spacing_m = 0.005;
  return o;
}

// Checks everything that does not depend on the robot.
void check_layout_and_order(const PlanResult& r, const std::vector<PartPoint>& parts) {
  ASSERT_TRUE(r.ok()) << r.message;
  const CubeGeometry& g = r.cube;
  const auto per_cube = static_cast<std::size_t>(g.n_nodes() + 1);
  ASSERT_EQ(r.locations.size(), parts.size() * per_cube);
  std::set<std::string> labels;
  std::map<int, int> targets;
  for (std::size_t k = 0; k < r.locations.size(); ++k) {
    const PlannedLocation& l = r.locations[k];
    EXPECT_TRUE(labels.insert(l.point).second) << l.point << " visited twice";
    const PartPoint& part = parts[static_cast<std::size_t>(l.part)];
    if (l.role == Role::kTarget) {
      ++targets[l.part];
      EXPECT_EQ(l.point, part.name);
      EXPECT_EIGEN_NEAR(l.robot_m, part.robot_m, 0.0);
    } else {
      EXPECT_LE((l.robot_m - part.robot_m).cwiseAbs().maxCoeff(), g.halfwidth_m + 1e-12);
    }
    // Each cube is one contiguous block; inside it fiducials follow each other one grid step
    // apart and the target sits between two corners of its cell.
    if (k % per_cube != 0) {
      const PlannedLocation& prev = r.locations[k - 1];
      EXPECT_EQ(prev.part, l.part);
      const double step = (l.robot_m - prev.robot_m).norm();
      const bool target_step = l.role == Role::kTarget || prev.role == Role::kTarget;
      EXPECT_NEAR(step, target_step ? g.d_min_m() : g.spacing_m, 1e-12) << l.point;
    }
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    EXPECT_EQ(targets[static_cast<int>(i)], 1);
    EXPECT_EQ(r.parts[i].n_fiducials, g.n_nodes());
    EXPECT_NEAR(r.parts[i].d_min_m, std::sqrt(3.0) / 2.0 * g.spacing_m, 1e-15);
  }
  EXPECT_LE(r.between_cubes_m, r.naive_between_cubes_m + 1e-12);
}

// Every location's joints reach it (FK) and are the IK solution nearest the part point's joints.
void check_joints(const SerialChain& chain, const PlanResult& r, const PlanOptions& o) {
  for (const PlannedLocation& l : r.locations) {
    const Eigen::Isometry3d t = kinematics::forward_kinematics(chain, l.q_rad);
    ASSERT_LE((t.translation() - l.robot_m).norm(), 1e-9) << l.point;
    ASSERT_LE(kinematics::rotation_angle_between(t.linear(), o.arm.R_base_tcp), 1e-9) << l.point;
    EXPECT_TRUE(chain.within_limits(l.q_rad)) << l.point;
    const PartPlan& part = r.parts[static_cast<std::size_t>(l.part)];
    EXPECT_EQ(*kinematics::configuration_of(chain, l.q_rad), l.config) << l.point;
    if (l.role == Role::kTarget) continue;
    kinematics::IkOptions all;
    all.apply_joint_limits = false;
    const kinematics::IkResult ik =
        kinematics::inverse_kinematics(chain, tcp_pose(l.robot_m, o.arm), o.arm.psi_rad, all);
    ASSERT_TRUE(ik.ok());
    const double chosen = (l.q_rad - part.q_rad).norm();  // travel, L2
    for (const kinematics::IkSolution& s : ik.solutions) {
      const auto shifted = kinematics::shift_nearest(chain, s.q_rad, part.q_rad);
      if (!shifted) continue;
      EXPECT_LE(chosen, (*shifted - part.q_rad).norm() + 1e-12)
          << l.point << ": configuration " << s.config.to_string() << " is nearer";
    }
    EXPECT_NEAR(l.joint_distance_rad, kinematics::joint_distance(l.q_rad, part.q_rad, o.arm.norm),
                1e-15);
  }
}

TEST(Plan, Ur5FourPartPoints) {
  const SerialChain chain = ur5_with_sphere();
  const std::vector<PartPoint> parts = four_parts();
  const PlanOptions o = options_10_5();
  const PlanResult r = make_plan(chain, parts, o);
  check_layout_and_order(r, parts);
  check_joints(chain, r, o);
  EXPECT_EQ(r.cube.nodes_per_axis, 6);
  EXPECT_TRUE(r.dmin.ok);
  EXPECT_TRUE(r.overlapping.empty());
  // Without home joints the part points take the first configuration the IK lists, and the
  // fiducials, only millimetres away, stay in it.
  for (const PartPlan& p : r.parts) {
    EXPECT_EQ(p.config.index(), 0);
    EXPECT_EQ(p.n_other_config, 0);
    EXPECT_LT(p.max_joint_distance_rad, 0.2);
  }
}

TEST(Plan, Ur5HomeJointsChooseThePartConfiguration) {
  const SerialChain chain = ur5_with_sphere();
  PlanOptions o = options_10_5();
  o.arm.norm = kinematics::JointNorm::kLinf;
  kinematics::JointVector home(6);
  home << 2.88, -1.66, 1.92, -1.83, -1.57, -1.83;  // ~ the UR5 test bed's home
  o.arm.home_q_rad = home;
  const PlanResult r = make_plan(chain, four_parts(), o);
  check_layout_and_order(r, four_parts());
  check_joints(chain, r, o);
  const kinematics::IkResult ik =
      kinematics::inverse_kinematics(chain, tcp_pose(four_parts()[0].robot_m, o.arm));
  double best = 1e9;
  for (const kinematics::IkSolution& s : ik.solutions) {
    best = std::min(best, kinematics::joint_distance_linf(s.q_rad, home));
  }
  EXPECT_NEAR(kinematics::joint_distance_linf(r.parts[0].q_rad, home), best, 1e-12);
}

TEST(Plan, Lwr4AtAFixedArmAngle) {
  const SerialChain chain =
      kinematics::lwr4().with_tool(Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.1)));
  const std::vector<PartPoint> parts{
      {"A", {0.48, 0.22, 0.30}}, {"B", {0.54, 0.22, 0.30}}, {"C", {0.54, 0.30, 0.31}}};
  PlanOptions o;
  o.halfwidth_m = 0.0075;
  o.spacing_m = 0.005;
  o.arm.psi_rad = -0.26;
  const PlanResult r = make_plan(chain, parts, o);
  check_layout_and_order(r, parts);
  check_joints(chain, r, o);
}

TEST(Plan, UnreachablePointsAreNamedNeverGuessed) {
  const SerialChain chain = ur5_with_sphere();
  std::vector<PartPoint> parts = four_parts();
  parts.push_back({"far_away", {1.5, 0.0, 0.25}});
  parts.push_back({"edge", {0.0, 0.0, 0.6}});  // above the base: inside the shoulder cylinder
  const PlanResult r = make_plan(chain, parts, options_10_5());
  EXPECT_EQ(r.status, PlanStatus::kUnreachable);
  EXPECT_TRUE(r.locations.empty());
  ASSERT_EQ(r.unreachable.size(), 2u);
  EXPECT_EQ(r.unreachable[0].point, "far_away");
  EXPECT_NE(r.message.find("far_away"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("edge"), std::string::npos) << r.message;
  // A cube reaching out of the workspace names the fiducials that cannot be reached.
  // (The part point itself is reachable, its outer fiducials are beyond the reach.)
  const PlanResult rim = make_plan(chain, {{"rim", {0.89, -0.11, 0.1}}}, options_10_5());
  EXPECT_EQ(rim.status, PlanStatus::kUnreachable);
  EXPECT_TRUE(rim.parts[0].reachable);
  ASSERT_FALSE(rim.unreachable.empty());
  for (const UnreachableLocation& u : rim.unreachable) {
    EXPECT_TRUE(u.point.starts_with("rim.f")) << u.point;
    EXPECT_NE(u.reason.find("reach"), std::string::npos) << u.reason;
  }
}

TEST(Plan, BadPartsAndOptionsThrow) {
  const SerialChain chain = ur5_with_sphere();
  const PlanOptions o = options_10_5();
  EXPECT_THROW(make_plan(chain, {}, o), InputError);
  EXPECT_THROW(make_plan(chain, {{"P", {0.4, 0, 0.2}}, {"P", {0.5, 0, 0.2}}}, o), InputError);
  EXPECT_THROW(make_plan(chain, {{"P", {NAN, 0, 0.2}}}, o), InputError);
  EXPECT_THROW(make_plan(chain, {{"", {0.4, 0, 0.2}}}, o), InputError);
  // A part named like another part's fiducial.
  EXPECT_THROW(make_plan(chain, {{"P", {0.4, 0, 0.2}}, {"P.f0-0-0", {0.5, 0, 0.2}}}, o),
               InputError);
  PlanOptions big = o;
  big.max_locations = 100;
  EXPECT_THROW(make_plan(chain, {{"P", {0.4, 0, 0.2}}}, big), InputError);
  PlanOptions no_noise = o;
  no_noise.sigma_noise_m = 0.0;
  EXPECT_THROW(make_plan(chain, {{"P", {0.4, 0, 0.2}}}, no_noise), InputError);
  PlanOptions wrong_home = o;
  wrong_home.arm.home_q_rad = kinematics::JointVector::Zero(7);
  EXPECT_THROW(make_plan(chain, {{"P", {0.4, 0, 0.2}}}, wrong_home), InputError);
}

TEST(Plan, OverlappingCubesAreReported) {
  const SerialChain chain = ur5_with_sphere();
  const PlanResult r =
      make_plan(chain, {{"P", {0.45, -0.1, 0.25}}, {"Q", {0.46, -0.1, 0.25}}}, options_10_5());
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.overlapping.size(), 1u);
  EXPECT_EQ(r.overlapping[0], (std::array<int, 2>{0, 1}));
}

}  // namespace
}  // namespace vrreg::planning
