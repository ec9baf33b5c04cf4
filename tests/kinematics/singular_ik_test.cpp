// SPDX-License-Identifier: Apache-2.0
// The IK property at every singularity: for joints drawn at random and for joints pinned at each
// singular value, FK(q) -> IK contains q (up to the free angle, which is passed as q's own) and
// FK of every solution reproduces the pose to 1e-12 m and 1e-11 rad. With the default free
// angle the IK must not refuse a pose FK produced either.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <string>

#include "kinematics_test_support.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/kinematics/ur_ik.hpp"
#include "vrreg_test.hpp"

namespace vrreg::kinematics {
namespace {

using testing::pose_error;
using testing::random_joints;
using units::kPi;

constexpr double kPositionTolerance = 1e-12;  // m
constexpr double kRotationTolerance = 1e-11;  // rad (UR, q3 = q5 = 0: 1.6e-12)
// rad: an angle found by the law of cosines counts as singular within 4.5e-5 rad of 0 or pi
// (1 - |cos| <= 1e-9), where its two branches collapse into one; a singular inverse also loses
// half the digits.
constexpr double kContainsTolerance = 1e-4;

// Pins a random joint vector onto a singular set; false when this draw cannot be pinned.
using Pin = std::function<bool(const SerialChain&, JointVector&, Random&)>;

struct Singularity {
  std::string name;
  Pin pin;
};

// UR shoulder singularity: the wrist centre on the joint-1 axis plane offset by d4, i.e. its
// reach along x1, h = a2 c2 + a3 c23 + d5 s234, is zero: solve s234 for h = 0.
bool pin_ur_shoulder(const SerialChain& chain, JointVector& q, Random& rng) {
  const double a2 = chain.row(1).a_m, a3 = chain.row(2).a_m, d5 = chain.row(4).d_m;
  const double px = a2 * std::cos(q(1)) + a3 * std::cos(q(1) + q(2));
  if (std::abs(px) > 0.9 * std::abs(d5)) return false;
  const double s234 = -px / d5;
  const double t234 = rng.uniform() < 0.5 ? std::asin(s234) : kPi - std::asin(s234);
  q(3) = wrap_angle(t234 - q(1) - q(2));
  return true;
}

std::vector<Singularity> ur_singularities() {
  const auto set = [](int joint, double value) {
    return [joint, value](const SerialChain&, JointVector& q, Random&) {
      q(joint) = value;
      return true;
    };
  };
  return {
      {"random", [](const SerialChain&, JointVector&, Random&) { return true; }},
      {"q5=0", set(4, 0.0)},
      {"q5=pi", set(4, kPi)},
      {"q5=-pi", set(4, -kPi)},
      {"q3=0", set(2, 0.0)},
      {"q3=pi", set(2, kPi)},
      {"shoulder", pin_ur_shoulder},
      {"q3=0,q5=0",
       [](const SerialChain&, JointVector& q, Random&) {
         q(2) = 0.0;
         q(4) = 0.0;
         return true;
       }},
      {"shoulder,q5=0",
       [](const SerialChain& chain, JointVector& q, Random& rng) {
         q(4) = 0.0;
         return pin_ur_shoulder(chain, q, rng);
       }},
  };
}

std::vector<Singularity> lwr_singularities() {
  const auto zero = [](std::vector<int> joints) {
    return [joints](const SerialChain&, JointVector& q, Random&) {
      for (const int j : joints) q(j) = 0.0;
      // Joints 3 and 7 share the free angle when both the shoulder and the wrist are singular.
      // (Joint 3's free angle is that of the base configuration: see check_pose.)
      if (joints.size() > 1) q(6) = wrap_angle(q(3) < 0.0 ? q(2) - kPi : q(2));
      return true;
    };
  };
  return {
      {"random", [](const SerialChain&, JointVector&, Random&) { return true; }},
      {"theta2=0", zero({1})},
      {"theta4=0", zero({3})},
      {"theta6=0", zero({5})},
      {"theta2=theta6=0", zero({1, 5})},
      {"theta2=theta4=theta6=0", zero({1, 3, 5})},
  };
}

struct Outcome {
  int poses = 0;
  int contained = 0;
  int refused_default = 0;
  double worst_m = 0.0;
  double worst_rad = 0.0;
};

// FK(q) -> IK(free angle `free`) and the checks; `contains` says whether q must be among them.
void check_pose(const SerialChain& chain, const JointVector& q, Outcome& out) {
  const Eigen::Isometry3d t = forward_kinematics(chain, q);
  IkOptions options;
  std::optional<double> psi;
  if (chain.family() == ChainFamily::kLwr) {
    psi = lwr_arm_state(chain, q).psi_rad;
    // The free angle is that of the base configuration, before the flips: an elbow flip (theta4
    // < 0) adds pi to joint 3; the shoulder and wrist flips collapse where their joint is 0.
    options.singular_free_angle_rad = q(3) < 0.0 ? q(2) - kPi : q(2);
    if (std::abs(std::sin(q(1))) > 1e-9) options.singular_free_angle_rad = q(6);
  } else {
    options.singular_free_angle_rad = q(5);
  }
  ++out.poses;
  // LWR: at a singular shoulder or wrist the default free angle (0) may put joint 1 or 5 outside
  // its +-170 deg; the free angle is not yet chosen within the limits there, so this check is
  // geometric only.
  IkOptions default_options;
  default_options.apply_joint_limits = chain.family() != ChainFamily::kLwr;
  for (const bool own_free_angle : {true, false}) {
    const IkResult r =
        inverse_kinematics(chain, t, psi, own_free_angle ? options : default_options);
    if (!r.ok()) {
      ADD_FAILURE() << chain.name() << " refused the pose of q = " << q.transpose() << " ("
                    << (own_free_angle ? "q's free angle" : "default free angle")
                    << "): " << r.message;
      ++out.refused_default;
      continue;
    }
    double nearest = 1e300;
    for (const IkSolution& s : r.solutions) {
      const auto e = pose_error(forward_kinematics(chain, s.q_rad), t);
      out.worst_m = std::max(out.worst_m, e.position_m);
      out.worst_rad = std::max(out.worst_rad, e.rotation_rad);
      nearest = std::min(nearest, joint_distance_linf(s.q_rad, q));
    }
    const bool contains = nearest <= kContainsTolerance;
    if (own_free_angle) {
      EXPECT_TRUE(contains) << std::setprecision(17) << chain.name() << ": q = " << q.transpose()
                            << " not among the " << r.solutions.size() << " solutions; nearest at "
                            << nearest << " rad";
      if (contains) ++out.contained;
    }
  }
}

void run_property(const SerialChain& chain, const std::vector<Singularity>& singularities,
                  int per_case) {
  for (const Singularity& s : singularities) {
    Random rng(2024);
    Outcome out;
    for (int k = 0; k < per_case; ++k) {
      JointVector q = random_joints(rng, chain);
      while (!s.pin(chain, q, rng) || !chain.within_limits(q)) q = random_joints(rng, chain);
      check_pose(chain, q, out);
    }
    EXPECT_LE(out.worst_m, kPositionTolerance) << chain.name() << " " << s.name;
    EXPECT_LE(out.worst_rad, kRotationTolerance) << chain.name() << " " << s.name;
    std::printf("[ %s %s ] %d poses, %d contain q, worst %.3g m %.3g rad\n", chain.name().c_str(),
                s.name.c_str(), out.poses, out.contained, out.worst_m, out.worst_rad);
  }
}

int cases() { return ::vrreg::testing::sanitized() ? 300 : 3000; }

TEST(SingularIk, UrFamilyInvertsEveryPoseAtEverySingularity) {
  for (const char* name : {"ur3", "ur5", "ur10", "ur5e"}) {
    run_property(*robot_by_name(name), ur_singularities(), cases());
  }
}

TEST(SingularIk, LwrInvertsEveryPoseAtEverySingularity) {
  run_property(lwr4(), lwr_singularities(), cases());
}

// The reproduction of the wrist-singular refusal: at q5 = 0 the free q6 moves the wrist (frame 4
// origin) on a circle of radius d5; q6 = 0 put it out of reach for a few percent of poses.
TEST(SingularIk, UrWristSingularPoseWithDefaultFreeAngleIsSolved) {
  const SerialChain chain = ur5();
  JointVector q(6);
  q << 1.33, -0.31, 0.81, -1.63, 0.0, 1.06;
  const Eigen::Isometry3d t = forward_kinematics(chain, q);
  const IkResult r = ur_inverse_kinematics(chain, t);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NE(r.singular & kWristSingular, 0);
  for (const IkSolution& s : r.solutions) {
    EXPECT_LE(pose_error(forward_kinematics(chain, s.q_rad), t).position_m, kPositionTolerance);
  }
}

}  // namespace
}  // namespace vrreg::kinematics
