// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/serial_chain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg::kinematics {
namespace {

using units::kPi;

TEST(SerialChain, BuiltinRobotsHaveTheirFamilies) {
  for (const char* name : {"ur3", "ur5", "ur10", "ur5e"}) {
    const auto chain = robot_by_name(name);
    ASSERT_TRUE(chain.has_value()) << name;
    EXPECT_EQ(chain->family(), ChainFamily::kUr) << name;
    EXPECT_EQ(chain->n_joints(), 6);
    EXPECT_EQ(chain->name(), name);
  }
  EXPECT_EQ(lwr4().family(), ChainFamily::kLwr);
  EXPECT_EQ(robot_by_name("LWR4")->n_joints(), 7);
  EXPECT_FALSE(robot_by_name("ur7").has_value());
  EXPECT_EQ(builtin_robot_names().size(), 5u);
}

TEST(SerialChain, DesignTableValues) {
  const SerialChain ur = ur5();
  EXPECT_DOUBLE_EQ(ur.row(0).d_m, 0.089159);
  EXPECT_DOUBLE_EQ(ur.row(1).a_m, -0.425);
  EXPECT_DOUBLE_EQ(ur.row(2).a_m, -0.39225);
  EXPECT_DOUBLE_EQ(ur.row(3).d_m, 0.10915);
  EXPECT_DOUBLE_EQ(ur.row(4).d_m, 0.09465);
  EXPECT_DOUBLE_EQ(ur.row(5).d_m, 0.0823);
  const SerialChain lwr = lwr4();
  EXPECT_DOUBLE_EQ(lwr.row(2).d_m, 0.40);
  EXPECT_DOUBLE_EQ(lwr.limit(1).upper_rad, 120.0 * kPi / 180.0);
  EXPECT_DOUBLE_EQ(lwr.limit(6).lower_rad, -170.0 * kPi / 180.0);
}

TEST(SerialChain, PerturbedTableLosesTheAnalyticFamily) {
  std::vector<DhRow> rows = ur5().rows();
  rows[3].alpha_rad += 1e-6;
  EXPECT_EQ(detect_family(rows), ChainFamily::kGeneric);
  rows = ur5().rows();
  rows[1].theta_offset_rad = 0.01;  // offsets and d2/d3 keep the structure
  rows[1].d_m = 0.02;
  EXPECT_EQ(detect_family(rows), ChainFamily::kUr);
  rows = lwr4().rows();
  rows[3].d_m = 0.001;
  EXPECT_EQ(detect_family(rows), ChainFamily::kGeneric);
}

TEST(SerialChain, RejectsBadInput) {
  const std::vector<DhRow> rows = ur5().rows();
  const std::vector<JointLimits> limits = ur5().limits();
  EXPECT_THROW(SerialChain("x", {}, {}), InputError);
  EXPECT_THROW(SerialChain("x", rows, {limits.begin(), limits.begin() + 5}), InputError);
  std::vector<DhRow> bad = rows;
  bad[2].d_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SerialChain("x", bad, limits), InputError);
  std::vector<JointLimits> bad_limits = limits;
  bad_limits[0] = {1.0, -1.0};
  EXPECT_THROW(SerialChain("x", rows, bad_limits), InputError);
  Eigen::Isometry3d not_rotation = Eigen::Isometry3d::Identity();
  not_rotation.linear()(0, 0) = 2.0;
  EXPECT_THROW(SerialChain("x", rows, limits, Eigen::Isometry3d::Identity(), not_rotation),
               InputError);
  Eigen::Isometry3d reflection = Eigen::Isometry3d::Identity();
  reflection.linear()(2, 2) = -1.0;
  EXPECT_THROW(static_cast<void>(ur5().with_base(reflection)), InputError);
  EXPECT_THROW(SerialChain("x", std::vector<DhRow>(13), std::vector<JointLimits>(13)), InputError);
}

TEST(SerialChain, WithinLimits) {
  const SerialChain chain = lwr4();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(7);
  EXPECT_TRUE(chain.within_limits(q));
  q(1) = 2.2;  // > 120 deg
  EXPECT_FALSE(chain.within_limits(q));
  EXPECT_FALSE(chain.within_limits(Eigen::VectorXd::Zero(6)));
}

TEST(Pose, RollPitchYawRoundTrip) {
  for (double roll : {-3.0, -0.4, 0.0, 1.2, 3.1}) {
    for (double pitch : {-1.5, -0.3, 0.0, 0.9, 1.5}) {
      for (double yaw : {-2.9, 0.0, 0.7, 3.0}) {
        const Eigen::Matrix3d r = rotation_from_rpy(roll, pitch, yaw);
        const Eigen::Vector3d rpy = rpy_from_rotation(r);
        EXPECT_NEAR(rotation_angle_between(rotation_from_rpy(rpy(0), rpy(1), rpy(2)), r), 0.0,
                    1e-14);
        EXPECT_NEAR(rpy(1), pitch, 1e-12);
      }
    }
  }
  // R = Rz(yaw) Ry(pitch) Rx(roll), checked on a vector.
  const Eigen::Matrix3d r = rotation_from_rpy(kPi / 2, 0.0, 0.0);
  EXPECT_NEAR((r * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
  const Eigen::Matrix3d locked = rotation_from_rpy(0.3, kPi / 2, 0.5);
  const Eigen::Vector3d rpy = rpy_from_rotation(locked);
  EXPECT_NEAR(rotation_angle_between(rotation_from_rpy(rpy(0), rpy(1), rpy(2)), locked), 0.0,
              1e-12);
}

}  // namespace
}  // namespace vrreg::kinematics
