// SPDX-License-Identifier: Apache-2.0
// Analytic IK (every solution) beside Orocos KDL's numeric IK (one solution per call, from a
// fixed seed) on the same 1024 random reachable poses (joints uniform within the limits).
// Counters: success_rate = fraction of poses solved (analytic: the sampled joints are among the
// solutions, to 1e-6 rad; KDL: status >= 0 and the pose reached to 1e-5 m and 1e-5 rad),
// solutions = mean number of solutions per call.
#include <benchmark/benchmark.h>

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>
#include <algorithm>
#include <numbers>
#include <vector>

#include "kdl_support.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/lwr_psi_intervals.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/kinematics/ur_ik.hpp"

namespace {

using vrreg::kinematics::JointVector;
using vrreg::kinematics::SerialChain;
constexpr int kPoses = 1024;

struct Sample {
  JointVector q;
  Eigen::Isometry3d pose;
  double psi_rad;
};

std::vector<Sample> make_samples(const SerialChain& chain) {
  vrreg::Random rng(7);
  std::vector<Sample> samples;
  for (int k = 0; k < kPoses; ++k) {
    JointVector q(chain.n_joints());
    for (int i = 0; i < chain.n_joints(); ++i) {
      q(i) = rng.uniform(chain.limit(i).lower_rad, chain.limit(i).upper_rad);
    }
    const double psi = chain.family() == vrreg::kinematics::ChainFamily::kLwr
                           ? vrreg::kinematics::lwr_arm_state(chain, q).psi_rad
                           : 0.0;
    samples.push_back({q, vrreg::kinematics::forward_kinematics(chain, q), psi});
  }
  return samples;
}

bool contains(const vrreg::kinematics::IkResult& r, const JointVector& q) {
  for (const auto& s : r.solutions) {
    if (vrreg::kinematics::joint_distance_linf(s.q_rad, q) < 1e-6) return true;
  }
  return false;
}

// Success rate and mean number of solutions over all samples, computed once outside the timed
// loop (PauseTiming would cost more than the call itself).
template <typename Solve>
void set_counters(benchmark::State& state, const std::vector<Sample>& samples, Solve solve) {
  double found = 0, solutions = 0;
  for (const Sample& s : samples) {
    const vrreg::kinematics::IkResult r = solve(s);
    found += contains(r, s.q) ? 1 : 0;
    solutions += static_cast<double>(r.solutions.size());
  }
  state.counters["success_rate"] = found / static_cast<double>(samples.size());
  state.counters["solutions"] = solutions / static_cast<double>(samples.size());
}

void BM_vrreg_ur5_ik_all_solutions(benchmark::State& state) {
  const SerialChain chain = vrreg::kinematics::ur5();
  const std::vector<Sample> samples = make_samples(chain);
  const auto solve = [&](const Sample& s) {
    return vrreg::kinematics::ur_inverse_kinematics(chain, s.pose);
  };
  std::size_t k = 0;
  for (auto _ : state) {
    auto r = solve(samples[k++ % samples.size()]);
    benchmark::DoNotOptimize(r);
  }
  set_counters(state, samples, solve);
}

void BM_vrreg_lwr4_ik_all_configurations(benchmark::State& state) {
  const SerialChain chain = vrreg::kinematics::lwr4();
  const std::vector<Sample> samples = make_samples(chain);
  vrreg::kinematics::IkOptions options;
  options.apply_joint_limits = state.range(0) != 0;
  const auto solve = [&](const Sample& s) {
    return vrreg::kinematics::lwr_inverse_kinematics(chain, s.pose, s.psi_rad, options);
  };
  std::size_t k = 0;
  for (auto _ : state) {
    auto r = solve(samples[k++ % samples.size()]);
    benchmark::DoNotOptimize(r);
  }
  set_counters(state, samples, solve);
}

void BM_vrreg_lwr4_feasible_psi(benchmark::State& state) {
  const SerialChain chain = vrreg::kinematics::lwr4();
  const std::vector<Sample> samples = make_samples(chain);
  std::size_t k = 0;
  for (auto _ : state) {
    auto r = vrreg::kinematics::lwr_feasible_psi(chain, samples[k++ % samples.size()].pose);
    benchmark::DoNotOptimize(r);
  }
}

void BM_vrreg_fk(benchmark::State& state) {
  const SerialChain chain =
      state.range(0) != 0 ? vrreg::kinematics::lwr4() : vrreg::kinematics::ur5();
  const std::vector<Sample> samples = make_samples(chain);
  std::size_t k = 0;
  for (auto _ : state) {
    auto t = vrreg::kinematics::forward_kinematics(chain, samples[k++ % samples.size()].q);
    benchmark::DoNotOptimize(t);
  }
}

// ---- Orocos KDL -------------------------------------------------------------------------------

// A typical non-singular home posture as the seed (what a user without a nearby guess passes).
KDL::JntArray seed(const SerialChain& chain) {
  constexpr double d = std::numbers::pi / 180.0;
  KDL::JntArray q(static_cast<unsigned>(chain.n_joints()));
  if (chain.n_joints() == 6) {
    q.data << 0.0, -90 * d, 90 * d, -90 * d, -90 * d, 0.0;
  } else {
    q.data << 0.0, 30 * d, 0.0, -60 * d, 0.0, 30 * d, 0.0;
  }
  return q;
}

// KDL set up for ~1e-6 accuracy: LMA with unit task-space weights (its default weighs rotation
// by 1e-2 and stops at ~5e-4 rad) and eps = 1e-12 on the squared error; NR_JL with its default
// eps = 1e-6 per twist component. Success = status >= 0 and the pose reached within 1e-5 m and
// 1e-5 rad.
bool reached(const SerialChain& chain, const KDL::JntArray& q, const Eigen::Isometry3d& target) {
  const Eigen::Isometry3d t = vrreg::kinematics::forward_kinematics(chain, q.data);
  return (t.translation() - target.translation()).norm() < 1e-5 &&
         vrreg::kinematics::rotation_angle_between(t.linear(), target.linear()) < 1e-5;
}

template <bool kLma>
void BM_kdl_ik(benchmark::State& state) {
  const SerialChain chain =
      state.range(0) != 0 ? vrreg::kinematics::lwr4() : vrreg::kinematics::ur5();
  const std::vector<Sample> samples = make_samples(chain);
  const KDL::Chain kdl = vrreg::bench::kdl_chain(chain);
  const unsigned n = kdl.getNrOfJoints();
  KDL::JntArray q_min(n), q_max(n);
  for (unsigned i = 0; i < n; ++i) {
    q_min(i) = chain.limit(static_cast<int>(i)).lower_rad;
    q_max(i) = chain.limit(static_cast<int>(i)).upper_rad;
  }
  KDL::ChainFkSolverPos_recursive fk(kdl);
  KDL::ChainIkSolverVel_pinv vel(kdl);
  KDL::ChainIkSolverPos_LMA lma(kdl, Eigen::Matrix<double, 6, 1>::Ones(), 1e-12);
  KDL::ChainIkSolverPos_NR_JL nr_jl(kdl, q_min, q_max, fk, vel);
  const KDL::JntArray q_init = seed(chain);
  KDL::JntArray q_out(n);
  const auto solve = [&](const Sample& s) {
    const KDL::Frame target = vrreg::bench::kdl_frame(s.pose);
    return kLma ? lma.CartToJnt(q_init, target, q_out) : nr_jl.CartToJnt(q_init, target, q_out);
  };
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solve(samples[k++ % samples.size()]));
    benchmark::ClobberMemory();
  }
  double found = 0;
  for (const Sample& s : samples) {
    found += solve(s) >= 0 && reached(chain, q_out, s.pose) ? 1 : 0;
  }
  state.counters["success_rate"] = found / static_cast<double>(samples.size());
  state.counters["solutions"] = found / static_cast<double>(samples.size());
}

// The fastest repetition: the least disturbed run on a shared machine.
double fastest_ik(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

}  // namespace

BENCHMARK(BM_vrreg_ur5_ik_all_solutions)
    ->Unit(benchmark::kMicrosecond)
    ->ComputeStatistics("min", fastest_ik);
BENCHMARK(BM_vrreg_lwr4_ik_all_configurations)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("limits")
    ->Unit(benchmark::kMicrosecond)
    ->ComputeStatistics("min", fastest_ik);
BENCHMARK(BM_vrreg_lwr4_feasible_psi)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_vrreg_fk)->Arg(0)->Arg(1)->ArgName("lwr")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_kdl_ik<true>)
    ->Name("BM_kdl_ik_lma")
    ->Arg(0)
    ->Arg(1)
    ->ArgName("lwr")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_kdl_ik<false>)
    ->Name("BM_kdl_ik_nr_jl")
    ->Arg(0)
    ->Arg(1)
    ->ArgName("lwr")
    ->Unit(benchmark::kMicrosecond);
