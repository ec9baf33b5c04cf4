// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/ur_ik.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "kinematics_test_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg::kinematics {
namespace {

using testing::pose_error;
using testing::pose_from;
using testing::random_joints;
using units::kPi;

// Away from the singular sets by `margin`: wrist (sin q5), elbow (sin q3), shoulder (reach h).
bool generic(const SerialChain& chain, const JointVector& q, double margin = 1e-3) {
  double t[6];
  for (int i = 0; i < 6; ++i) t[i] = q(i) + chain.row(i).theta_offset_rad;
  const double t23 = t[1] + t[2], t234 = t23 + t[3];
  const double px = chain.row(1).a_m * std::cos(t[1]) + chain.row(2).a_m * std::cos(t23);
  const double h = px + chain.row(4).d_m * std::sin(t234);
  return std::abs(std::sin(t[4])) > margin && std::abs(std::sin(t[2])) > margin &&
         std::abs(h) > margin;
}

struct Stats {
  long poses = 0, solutions = 0, found = 0, tested = 0;
  double worst_m = 0.0, worst_rad = 0.0;
};

Stats round_trip(const SerialChain& chain, int n, std::uint64_t seed) {
  Random rng(seed);
  Stats s;
  for (int k = 0; k < n; ++k) {
    const JointVector q = random_joints(rng, chain);
    const Eigen::Isometry3d t = forward_kinematics(chain, q);
    const IkResult r = ur_inverse_kinematics(chain, t);
    ++s.poses;
    EXPECT_TRUE(r.ok()) << r.message;
    std::set<int> labels;
    bool contains = false;
    for (const IkSolution& sol : r.solutions) {
      ++s.solutions;
      const auto e = pose_error(forward_kinematics(chain, sol.q_rad), t);
      s.worst_m = std::max(s.worst_m, e.position_m);
      s.worst_rad = std::max(s.worst_rad, e.rotation_rad);
      EXPECT_TRUE(chain.within_limits(sol.q_rad));
      EXPECT_EQ(ur_configuration(chain, sol.q_rad), sol.config) << sol.config.to_string();
      labels.insert(sol.config.index());
      contains = contains || joint_distance_linf(sol.q_rad, q) < 1e-7;
    }
    EXPECT_EQ(labels.size(), r.solutions.size()) << "labels must be distinct";
    if (generic(chain, q)) {
      ++s.tested;
      if (contains) ++s.found;
    }
  }
  return s;
}

class UrRoundTrip : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(UrRoundTrip, EveryBranchMapsBackAndTheIkIsComplete) {
  const SerialChain chain = *robot_by_name(GetParam().first);
  int n = GetParam().second;
  if (::vrreg::testing::sanitized()) n = std::min(n, 20000);
  const Stats s = round_trip(chain, n, 12345);
  EXPECT_EQ(s.poses, n);
  EXPECT_LE(s.worst_m, 1e-9);
  EXPECT_LE(s.worst_rad, 1e-9);
  const double completeness = static_cast<double>(s.found) / static_cast<double>(s.tested);
  EXPECT_GE(completeness, 0.9999);
  EXPECT_GE(s.tested, n * 9 / 10);
  RecordProperty("poses", static_cast<int>(s.poses));
  RecordProperty("solutions", static_cast<int>(s.solutions));
  std::printf("[ %s ] %ld poses, %ld solutions, worst %.3g m %.3g rad, completeness %ld/%ld\n",
              chain.name().c_str(), s.poses, s.solutions, s.worst_m, s.worst_rad, s.found,
              s.tested);
}

INSTANTIATE_TEST_SUITE_P(Robots, UrRoundTrip,
                         ::testing::Values(std::pair{"ur5", 100000}, std::pair{"ur3", 20000},
                                           std::pair{"ur10", 20000}, std::pair{"ur5e", 20000}));

TEST(UrIk, GenericPoseHasEightDistinctLabelledSolutions) {
  const SerialChain chain = ur5();
  const IkResult r = ur_inverse_kinematics(chain, pose_from({0.3, 0.2, 0.4}, 0.3, 2.6, -0.4));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.solutions.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(r.solutions[static_cast<std::size_t>(i)].config.index(), i);
  EXPECT_EQ(r.singular, kNoSingularity);
}

TEST(UrIk, ToolAndBaseTransformsAreHonoured) {
  const SerialChain chain = ur10()
                                .with_tool(pose_from({0.01, 0.0, 0.12}, 0.0, 0.2, 0.0))
                                .with_base(pose_from({1.0, 2.0, 0.5}, 0.0, 0.0, 1.0));
  Random rng(9);
  for (int k = 0; k < 1000; ++k) {
    const JointVector q = random_joints(rng, chain);
    const Eigen::Isometry3d t = forward_kinematics(chain, q);
    const IkResult r = ur_inverse_kinematics(chain, t);
    ASSERT_TRUE(r.ok());
    for (const IkSolution& s : r.solutions) {
      const auto e = pose_error(forward_kinematics(chain, s.q_rad), t);
      EXPECT_LE(e.position_m, 1e-9);
      EXPECT_LE(e.rotation_rad, 1e-9);
    }
  }
}

TEST(UrIk, CalibratedOffsetsKeepTheIkExact) {
  std::vector<DhRow> rows = ur5().rows();
  for (int i = 0; i < 6; ++i) rows[static_cast<std::size_t>(i)].theta_offset_rad = 0.01 * (i + 1);
  rows[1].d_m = 0.003;
  rows[2].d_m = -0.001;
  const SerialChain chain("ur5-cal", rows, ur5().limits());
  ASSERT_EQ(chain.family(), ChainFamily::kUr);
  const Stats s = round_trip(chain, 5000, 4);
  EXPECT_LE(s.worst_m, 1e-9);
  EXPECT_LE(s.worst_rad, 1e-9);
  EXPECT_EQ(s.found, s.tested);
}

TEST(UrIk, WristSingularityUsesTheStatedQ6AndIsFlagged) {
  const SerialChain chain = ur5();
  JointVector q(6);
  q << 0.3, -1.2, 1.4, -0.5, 0.0, 0.7;  // q5 = 0: joints 4 and 6 aligned
  const Eigen::Isometry3d t = forward_kinematics(chain, q);
  IkOptions options;
  options.singular_free_angle_rad = 0.25;
  const IkResult r = ur_inverse_kinematics(chain, t, options);
  ASSERT_TRUE(r.ok());
  EXPECT_NE(r.singular & kWristSingular, 0);
  int n_singular = 0;
  for (const IkSolution& s : r.solutions) {
    // Only the shoulder branch of q has sin q5 = 0; there the flip pair collapses (q6 is free).
    if ((s.singular & kWristSingular) != 0) {
      ++n_singular;
      EXPECT_DOUBLE_EQ(s.q_rad(5), 0.25);
      EXPECT_FALSE(s.config.wrist_flipped());
    }
    EXPECT_LE(pose_error(forward_kinematics(chain, s.q_rad), t).position_m, 1e-12);
    EXPECT_LE(pose_error(forward_kinematics(chain, s.q_rad), t).rotation_rad, 1e-12);
  }
  EXPECT_EQ(n_singular, 2);  // elbow up and down
}

TEST(UrIk, ElbowAndShoulderSingularitiesAreFlagged) {
  const SerialChain chain = ur5();
  JointVector stretched(6);
  stretched << 0.2, -0.7, 0.0, 0.4, 1.0, 0.3;
  const IkResult r = ur_inverse_kinematics(chain, forward_kinematics(chain, stretched));
  ASSERT_TRUE(r.ok());
  EXPECT_NE(r.singular & kElbowSingular, 0);
  for (const IkSolution& s : r.solutions) {
    EXPECT_LE(pose_error(forward_kinematics(chain, s.q_rad), forward_kinematics(chain, stretched))
                  .position_m,
              1e-9);
  }
  // Wrist centre exactly at distance d4 from the joint-1 axis: h = 0.
  const double d4 = chain.row(3).d_m;
  Eigen::Isometry3d t = pose_from({0.0, 0.0, 0.5}, 0.0, 0.0, 0.0);
  t.translation() = Eigen::Vector3d(d4, 0.0, 0.5) + chain.row(5).d_m * t.linear().col(2);
  const IkResult s = ur_inverse_kinematics(chain, t);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_NE(s.singular & kShoulderSingular, 0);
  for (const IkSolution& sol : s.solutions) {
    EXPECT_LE(pose_error(forward_kinematics(chain, sol.q_rad), t).position_m, 1e-9);
  }
}

TEST(UrIk, UnreachablePosesGiveAReasonNotAnException) {
  const SerialChain chain = ur5();
  const IkResult far = ur_inverse_kinematics(chain, pose_from({2.0, 0.0, 0.3}, 0, 0, 0));
  EXPECT_EQ(far.status, IkStatus::kUnreachable);
  EXPECT_TRUE(far.solutions.empty());
  EXPECT_NE(far.message.find("reach"), std::string::npos) << far.message;
  // Wrist centre on the base axis: inside the d4 cylinder.
  Eigen::Isometry3d t = pose_from({0.0, 0.0, 0.4}, 0.0, 0.0, 0.0);
  t.translation() = Eigen::Vector3d(0.0, 0.0, 0.4) + chain.row(5).d_m * t.linear().col(2);
  const IkResult inside = ur_inverse_kinematics(chain, t);
  EXPECT_EQ(inside.status, IkStatus::kUnreachable);
  EXPECT_NE(inside.message.find("cylinder"), std::string::npos) << inside.message;
}

TEST(UrIk, JointLimitsFilterAndShift) {
  std::vector<JointLimits> limits = ur5().limits();
  limits[0] = {0.0, 2 * kPi};  // only non-negative q1: some branches need the +2 pi shift
  limits[2] = {0.0, kPi};      // elbow: only q3 >= 0
  const SerialChain chain("ur5-limited", ur5().rows(), limits);
  Random rng(31);
  for (int k = 0; k < 2000; ++k) {
    JointVector q = random_joints(rng, chain);
    const Eigen::Isometry3d t = forward_kinematics(chain, q);
    const IkResult r = ur_inverse_kinematics(chain, t);
    ASSERT_TRUE(r.ok());
    IkOptions unlimited;
    unlimited.apply_joint_limits = false;
    const std::size_t n_all = ur_inverse_kinematics(chain, t, unlimited).solutions.size();
    EXPECT_EQ(r.solutions.size() + static_cast<std::size_t>(r.n_outside_limits), n_all);
    for (const IkSolution& s : r.solutions) {
      EXPECT_TRUE(chain.within_limits(s.q_rad));
      EXPECT_LE(pose_error(forward_kinematics(chain, s.q_rad), t).position_m, 1e-9);
    }
  }
  std::vector<JointLimits> impossible = ur5().limits();
  impossible[4] = {0.1, 0.2};
  const SerialChain narrow("ur5-narrow", ur5().rows(), impossible);
  const IkResult r = ur_inverse_kinematics(narrow, pose_from({0.3, 0.2, 0.4}, 0.3, 2.6, -0.4));
  EXPECT_EQ(r.status, IkStatus::kOutsideLimits);
  EXPECT_EQ(r.n_outside_limits, 8);
}

TEST(UrIk, NearestSolutionIsTheControllersChoiceWithTwoPiShifts) {
  const SerialChain chain = ur5();
  Random rng(8);
  for (int k = 0; k < 2000; ++k) {
    const JointVector q = random_joints(rng, chain);  // in +-2 pi: often a shifted branch
    if (!generic(chain, q, 0.05)) continue;
    const Eigen::Isometry3d t = forward_kinematics(chain, q);
    JointVector current = q;
    for (int i = 0; i < 6; ++i) current(i) += rng.uniform(-1e-3, 1e-3);
    if (!chain.within_limits(current)) continue;
    const IkResult r = ur_inverse_kinematics_nearest(chain, t, current);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.solutions.size(), 1u);
    // The very joints (not a 2 pi shift of them) are returned.
    EXPECT_LE((r.solutions[0].q_rad - q).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_EQ(r.solutions[0].config, ur_configuration(chain, q));
  }
}

TEST(UrIk, NearestPrefersTheShiftNearTheCurrentJoints) {
  const SerialChain chain = ur5();
  JointVector q(6);
  q << 3.0, -1.0, 1.2, -0.6, 1.1, 0.4;
  const Eigen::Isometry3d t = forward_kinematics(chain, q);
  JointVector current = q;
  current(0) = 3.0 - 2 * kPi + 0.01;  // the same joint-1 angle, one turn lower
  const IkResult r = ur_inverse_kinematics_nearest(chain, t, current, JointNorm::kLinf);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.solutions[0].q_rad(0), 3.0 - 2 * kPi, 1e-9);
  EXPECT_THROW(ur_inverse_kinematics_nearest(chain, t, Eigen::VectorXd::Zero(5)), InputError);
}

TEST(UrIk, BadInputThrows) {
  const SerialChain chain = ur5();
  Eigen::Isometry3d t = pose_from({0.3, 0.2, 0.4}, 0, 0, 0);
  t.linear()(0, 1) = 0.5;
  EXPECT_THROW(ur_inverse_kinematics(chain, t), InputError);
  t = pose_from({std::nan(""), 0.2, 0.4}, 0, 0, 0);
  EXPECT_THROW(ur_inverse_kinematics(chain, t), InputError);
  EXPECT_THROW(ur_inverse_kinematics(lwr4(), pose_from({0.3, 0.2, 0.4}, 0, 0, 0)), InputError);
  IkOptions bad;
  bad.singular_tolerance = -1.0;
  EXPECT_THROW(ur_inverse_kinematics(chain, pose_from({0.3, 0.2, 0.4}, 0, 0, 0), bad), InputError);
}

}  // namespace
}  // namespace vrreg::kinematics
