// SPDX-License-Identifier: Apache-2.0
// vrreg's numerical IK beside Orocos KDL's LMA and NR_JL on chains no closed form covers: a UR5
// with a 5 cm shoulder offset (6R), the 7-axis arm of tests/data/urdf/arm7.urdf (Panda-like
// offsets) and the UR5 on a 2 m linear axis (tests/data/urdf/ur5_on_rail.urdf, 7 joints, one
// prismatic). 256 random reachable poses per chain (joints uniform within the limits).
// Counters: success_rate = fraction of poses solved (vrreg: status ok, every solution reaches
// the pose to 5e-13 m and rad by construction; KDL: status >= 0 and the pose reached within 1e-5 m
// and 1e-5 rad), solutions = mean number of configuration classes returned.
#include <benchmark/benchmark.h>

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>
#include <string>
#include <vector>

#include "kdl_support.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/numeric_ik.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/robot_io/urdf_robot.hpp"

namespace {

using vrreg::kinematics::JointVector;
using vrreg::kinematics::SerialChain;
constexpr int kNumericPoses = 256;

SerialChain numeric_chain(int which) {
  if (which == 0) {
    std::vector<vrreg::kinematics::DhRow> rows = vrreg::kinematics::ur5().rows();
    rows[0].a_m = 0.05;
    return SerialChain("offset-ur5", rows,
                       std::vector<vrreg::kinematics::JointLimits>(6, {-3.14159, 3.14159}));
  }
  const std::string file = which == 1 ? "arm7.urdf" : "ur5_on_rail.urdf";
  return vrreg::io::read_urdf_robot(std::string(VRREG_SOURCE_DIR) + "/tests/data/urdf/" + file);
}

struct Target {
  JointVector q;
  Eigen::Isometry3d pose;
};

std::vector<Target> targets(const SerialChain& chain) {
  vrreg::Random rng(11);
  std::vector<Target> out;
  for (int k = 0; k < kNumericPoses; ++k) {
    JointVector q(chain.n_joints());
    for (int i = 0; i < chain.n_joints(); ++i) {
      q(i) = rng.uniform(chain.limit(i).lower_rad, chain.limit(i).upper_rad);
    }
    out.push_back({q, vrreg::kinematics::forward_kinematics(chain, q)});
  }
  return out;
}

// range(0): chain; range(1): 1 = the first solution only, 0 = every class the search finds.
void BM_vrreg_numeric_ik(benchmark::State& state) {
  const SerialChain chain = numeric_chain(static_cast<int>(state.range(0)));
  const std::vector<Target> poses = targets(chain);
  vrreg::kinematics::NumericIkOptions options;
  if (state.range(1) != 0) options.max_solutions = 1;
  std::size_t k = 0;
  for (auto _ : state) {
    auto r = vrreg::kinematics::numeric_inverse_kinematics(chain, poses[k++ % poses.size()].pose,
                                                           options);
    benchmark::DoNotOptimize(r);
  }
  double solved = 0, solutions = 0;
  for (const Target& t : poses) {
    const auto r = vrreg::kinematics::numeric_inverse_kinematics(chain, t.pose, options);
    solved += r.ok() ? 1 : 0;
    solutions += static_cast<double>(r.solutions.size());
  }
  state.counters["success_rate"] = solved / kNumericPoses;
  state.counters["solutions"] = solutions / kNumericPoses;
}

// The pose of the last DH frame: KDL's chain has no base or tool transform.
Eigen::Isometry3d flange_target(const SerialChain& chain, const JointVector& q) {
  return vrreg::kinematics::flange_in_dh0(chain, q);
}

// range(0): chain; range(1): 1 = LMA, 0 = NR_JL. Seed: the middle of the limits (TRAC-IK's
// benchmark seeds the same way), one call per pose as KDL is used.
void BM_kdl_numeric_ik(benchmark::State& state) {
  const SerialChain chain = numeric_chain(static_cast<int>(state.range(0)));
  const std::vector<Target> poses = targets(chain);
  const KDL::Chain kdl = vrreg::bench::kdl_chain(chain);
  const unsigned n = kdl.getNrOfJoints();
  KDL::JntArray q_min(n), q_max(n), q_init(n), q_out(n);
  for (unsigned i = 0; i < n; ++i) {
    q_min(i) = chain.limit(static_cast<int>(i)).lower_rad;
    q_max(i) = chain.limit(static_cast<int>(i)).upper_rad;
    q_init(i) = 0.5 * (q_min(i) + q_max(i));
  }
  KDL::ChainFkSolverPos_recursive fk(kdl);
  KDL::ChainIkSolverVel_pinv vel(kdl);
  KDL::ChainIkSolverPos_LMA lma(kdl, Eigen::Matrix<double, 6, 1>::Ones(), 1e-12);
  KDL::ChainIkSolverPos_NR_JL nr_jl(kdl, q_min, q_max, fk, vel);
  const bool use_lma = state.range(1) != 0;
  const auto solve = [&](const Target& t) {
    const KDL::Frame target = vrreg::bench::kdl_frame(flange_target(chain, t.q));
    return use_lma ? lma.CartToJnt(q_init, target, q_out) : nr_jl.CartToJnt(q_init, target, q_out);
  };
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solve(poses[k++ % poses.size()]));
    benchmark::ClobberMemory();
  }
  double solved = 0;
  for (const Target& t : poses) {
    if (solve(t) < 0) continue;
    const Eigen::Isometry3d reached_pose = vrreg::kinematics::flange_in_dh0(chain, q_out.data);
    const Eigen::Isometry3d wanted = flange_target(chain, t.q);
    const bool in_limits = chain.within_limits(q_out.data, 1e-9);
    solved += in_limits && (reached_pose.translation() - wanted.translation()).norm() < 1e-5 &&
                      vrreg::kinematics::rotation_angle_between(reached_pose.linear(),
                                                                wanted.linear()) < 1e-5
                  ? 1
                  : 0;
  }
  state.counters["success_rate"] = solved / kNumericPoses;
  state.counters["solutions"] = solved / kNumericPoses;
}

}  // namespace

BENCHMARK(BM_vrreg_numeric_ik)
    ->ArgsProduct({{0, 1, 2}, {1, 0}})
    ->ArgNames({"chain", "first"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_kdl_numeric_ik)
    ->ArgsProduct({{0, 1, 2}, {1, 0}})
    ->ArgNames({"chain", "lma"})
    ->Unit(benchmark::kMicrosecond);
