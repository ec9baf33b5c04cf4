// SPDX-License-Identifier: Apache-2.0
// Strategy 3 of Procedure 2 (paper section 4.4): the nearest-configuration choice at each cube
// corner on hand-made joints, the seeded volume-corner registration, and exact correction when an
// arm's error is affine and every corner is taken in the target's arm.
#include <gtest/gtest.h>

#include <numbers>
#include <set>

#include "vrreg/core/check.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/planning/strategy3_correction.hpp"
#include "vrreg/planning/strategy3_registration.hpp"
#include "vrreg_test.hpp"

namespace vrreg::planning {
namespace {

constexpr double kHalf = 0.01;  // cube edge 20 mm around the origin

Location fiducial(std::size_t corner, int config, std::vector<double> q) {
  Location f;
  f.point = "C" + std::to_string(corner);
  f.config = config;
  f.robot_m = Eigen::Vector3d(corner & 1U ? kHalf : -kHalf, corner & 2U ? kHalf : -kHalf,
                              corner & 4U ? kHalf : -kHalf);
  f.q_rad = std::move(q);
  f.n_readings = 1;
  return f;
}

// Three configurations at each corner, listed config 3, 1, 2 (so index != config).
// Target joints (0, 0). Corners 0-3: config 1 (0.3, 0.3) is nearest in Linf, config 2 (0.4, 0)
// in L2. Corners 4-5: config 2 at 6.2 rad wraps to -0.083 rad: nearest in both. Corners 6-7:
// config 3 (0.05, 0.05) nearest in both.
std::vector<Location> hand_made_fiducials() {
  std::vector<Location> out;
  for (std::size_t c = 0; c < 8; ++c) {
    if (c < 4) {
      out.push_back(fiducial(c, 3, {2.0, 2.0}));
      out.push_back(fiducial(c, 1, {0.3, 0.3}));
      out.push_back(fiducial(c, 2, {0.4, 0.0}));
    } else if (c < 6) {
      out.push_back(fiducial(c, 3, {1.0, 1.0}));
      out.push_back(fiducial(c, 1, {-0.5, 0.0}));
      out.push_back(fiducial(c, 2, {6.2, 0.0}));
    } else {
      out.push_back(fiducial(c, 3, {0.05, 0.05}));
      out.push_back(fiducial(c, 1, {0.3, 0.3}));
      out.push_back(fiducial(c, 2, {0.4, 0.0}));
    }
  }
  return out;
}

Location target(std::vector<double> q) {
  Location t;
  t.point = "T";
  t.role = Role::kTarget;
  t.config = 1;
  t.q_rad = std::move(q);
  return t;
}

std::vector<int> chosen_configs(const Stencil& s, const std::vector<Location>& fiducials) {
  std::vector<int> out;
  for (int k = 0; k < s.size; ++k) {
    out.push_back(
        *fiducials[static_cast<std::size_t>(s.fiducial[static_cast<std::size_t>(k)])].config);
  }
  return out;
}

TEST(Strategy3Stencils, EachCornerTakesTheConfigurationNearestTheTarget) {
  const std::vector<Location> f = hand_made_fiducials();
  Strategy3CorrectionOptions options;
  options.cube_edge_m = 2 * kHalf;
  const std::vector<Stencil> l2 = nearest_configuration_stencils(f, {target({0.0, 0.0})}, options);
  ASSERT_EQ(l2.size(), 1U);
  EXPECT_EQ(l2[0].status, StencilStatus::kOk);
  EXPECT_EQ(l2[0].size, 8);
  EXPECT_EQ(chosen_configs(l2[0], f), (std::vector<int>{2, 2, 2, 2, 2, 2, 3, 3}));
  for (std::size_t c = 0; c < 8; ++c) {
    EXPECT_DOUBLE_EQ(l2[0].weight[c], 0.125);
    EXPECT_EQ(f[static_cast<std::size_t>(l2[0].fiducial[c])].point, "C" + std::to_string(c));
  }
  options.norm = kinematics::JointNorm::kLinf;
  const std::vector<Stencil> linf =
      nearest_configuration_stencils(f, {target({0.0, 0.0})}, options);
  EXPECT_EQ(chosen_configs(linf[0], f), (std::vector<int>{1, 1, 1, 1, 2, 2, 3, 3}));
}

TEST(Strategy3Stencils, MissingCornerAndBadInput) {
  std::vector<Location> f = hand_made_fiducials();
  Strategy3CorrectionOptions options;
  options.cube_edge_m = 2 * kHalf;
  Location far = target({0.0, 0.0});
  far.robot_m = Eigen::Vector3d(0.02, 0.0, 0.0);
  EXPECT_EQ(nearest_configuration_stencils(f, {far}, options)[0].status,
            StencilStatus::kMissingCorner);
  EXPECT_THROW(nearest_configuration_stencils(f, {target({})}, options), InputError);
  EXPECT_THROW(nearest_configuration_stencils(f, {target({0.0, 0.0, 0.0})}, options), InputError);
  options.cube_edge_m = 0.0;
  EXPECT_THROW(nearest_configuration_stencils(f, {target({0.0, 0.0})}, options), InputError);
}

// Two arms on a 3 x 3 x 3 grid (20 mm): arm 1 joints ~0, arm 2 joints ~3; each arm's robot error
// is affine (a different small linear map plus offset), so RRBC from same-arm corners is exact.
struct TwoArmGrid {
  std::vector<Location> fiducials;
  std::vector<Location> targets;
  RigidTransform T_sensor_robot;
};

Eigen::Vector3d arm_error_m(const Eigen::Vector3d& p, int arm) {
  Eigen::Matrix3d A;
  A << 1e-3, 2e-3, 0, 0, -1e-3, 1e-3, 2e-3, 0, 1e-3;
  return arm == 1 ? Eigen::Vector3d(A * p)
                  : Eigen::Vector3d(-2.0 * A.transpose() * p) + Eigen::Vector3d(4e-4, -3e-4, 5e-4);
}

TwoArmGrid two_arm_grid() {
  TwoArmGrid g;
  Random rng(3);
  g.T_sensor_robot = testing::random_transform(rng, 1.0);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        for (int arm = 1; arm <= 2; ++arm) {
          Location loc;
          loc.point = "P" + std::to_string(i) + std::to_string(j) + std::to_string(k);
          loc.config = arm;
          loc.robot_m = 0.02 * Eigen::Vector3d(i, j, k);
          loc.sensor_m = g.T_sensor_robot.apply(loc.robot_m + arm_error_m(loc.robot_m, arm));
          loc.q_rad = {arm == 1 ? 0.1 * i : 3.0 + 0.1 * i, arm == 1 ? 0.1 * j : -3.0};
          loc.n_readings = 1;
          const bool centre = i == 1 && j == 1 && k == 1;
          loc.role = centre ? Role::kTarget : Role::kFiducial;
          (centre ? g.targets : g.fiducials).push_back(loc);
        }
  return g;
}

TEST(Strategy3Registration, SeededRandomCornerConfigurations) {
  const TwoArmGrid g = two_arm_grid();
  Strategy3Options options;
  std::set<std::array<std::size_t, 8>> choices;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    options.seed = seed;
    const Strategy3Registration r = register_volume_corners(g.fiducials, options);
    EXPECT_EQ(r.corner_fiducials, register_volume_corners(g.fiducials, options).corner_fiducials);
    choices.insert(r.corner_fiducials);
    for (std::size_t c = 0; c < 8; ++c) {
      const Eigen::Vector3d corner(c & 1U ? 0.04 : 0.0, c & 2U ? 0.04 : 0.0, c & 4U ? 0.04 : 0.0);
      EXPECT_LT((g.fiducials[r.corner_fiducials[c]].robot_m - corner).norm(), 1e-12);
    }
    EXPECT_EQ(r.corrections_sensor_m.cols(), static_cast<Eigen::Index>(g.fiducials.size()));
  }
  EXPECT_GT(choices.size(), 5U);  // 2^8 possible choices
}

TEST(Strategy3Registration, RigidDataRegistersExactly) {
  TwoArmGrid g = two_arm_grid();
  for (Location& f : g.fiducials) f.sensor_m = g.T_sensor_robot.apply(f.robot_m);
  const Strategy3Registration r = register_volume_corners(g.fiducials, {});
  EXPECT_LT(r.registration.fre_m, 1e-12);
  EXPECT_LT(r.corrections_sensor_m.cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_THROW(register_volume_corners({g.fiducials.begin(), g.fiducials.begin() + 7}, {}),
               InputError);
}

TEST(Strategy3Correction, ExactWhenEveryCornerIsInTheTargetsArm) {
  const TwoArmGrid g = two_arm_grid();
  const Strategy3Registration r = register_volume_corners(g.fiducials, {});
  Strategy3CorrectionOptions options;
  options.cube_edge_m = 0.04;
  const TargetCorrection c = correct_targets_strategy3(r.registration.T_robot_sensor, g.fiducials,
                                                         r.corrections_sensor_m, g.targets, options);
  ASSERT_EQ(c.n_flagged, 0);
  Points3 targets_robot(3, 2);
  for (std::size_t t = 0; t < 2; ++t)
    targets_robot.col(static_cast<Eigen::Index>(t)) = g.targets[t].robot_m;
  const Eigen::VectorXd unc = point_errors(c.uncorrected_robot_m, targets_robot);
  const Eigen::VectorXd cor = point_errors(c.corrected_robot_m, targets_robot);
  EXPECT_GT(unc.minCoeff(), 1e-4);
  EXPECT_LT(cor.maxCoeff(), 1e-10);
  for (std::size_t t = 0; t < 2; ++t) {
    for (int k = 0; k < 8; ++k) {
      const Location& f = g.fiducials[static_cast<std::size_t>(
          c.stencils[t].fiducial[static_cast<std::size_t>(k)])];
      EXPECT_EQ(f.config, g.targets[t].config);
    }
  }
}

}  // namespace
}  // namespace vrreg::planning
