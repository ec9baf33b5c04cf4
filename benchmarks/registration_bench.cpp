// SPDX-License-Identifier: Apache-2.0
// Registration (Eq. 2) beside Eigen::umeyama (scaling off), and sigma_L (Eq. 1) over all pairs.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "vrreg/core/random.hpp"
#include "vrreg/metrics/rigid_body.hpp"
#include "vrreg/registration/rigid.hpp"

namespace {

struct Data {
  vrreg::Points3 sensor;
  vrreg::Points3 robot;
};

Data make_data(Eigen::Index n) {
  vrreg::Random rng(2024);
  Data d{vrreg::Points3(3, n), vrreg::Points3(3, n)};
  vrreg::RigidTransform t;
  t.rotation = rng.rotation();
  t.translation_m = Eigen::Vector3d(1.2, -0.4, 2.1);
  for (Eigen::Index j = 0; j < n; ++j) {
    d.sensor.col(j) = Eigen::Vector3d(rng.uniform(-0.15, 0.15), rng.uniform(-0.15, 0.15),
                                      rng.uniform(-0.1, 0.1));
    d.robot.col(j) = t.apply(d.sensor.col(j)) + rng.normal3(0.5e-3);
  }
  return d;
}

void BM_vrreg_register_rigid(benchmark::State& state) {
  const Data d = make_data(state.range(0));
  for (auto _ : state) {
    auto r = vrreg::register_rigid(d.sensor, d.robot);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The fast path: transform and FRE from one pass of moments, no per-point residuals.
void BM_vrreg_register_rigid_no_residuals(benchmark::State& state) {
  const Data d = make_data(state.range(0));
  vrreg::RegistrationOptions options;
  options.residuals = false;
  for (auto _ : state) {
    auto r = vrreg::register_rigid(d.sensor, d.robot, options);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The peer: Eigen's Umeyama without scaling. It returns only the transform (no FRE, residuals or
// degeneracy check), so it does less work than vrreg's call.
void BM_eigen_umeyama(benchmark::State& state) {
  const Data d = make_data(state.range(0));
  for (auto _ : state) {
    Eigen::Matrix4d t = Eigen::umeyama(d.sensor, d.robot, false);
    benchmark::DoNotOptimize(t);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_vrreg_sigma_l(benchmark::State& state) {
  const Data d = make_data(state.range(0));
  for (auto _ : state) {
    auto s = vrreg::rigid_body_statistics(d.sensor, d.robot);
    benchmark::DoNotOptimize(s);
  }
  state.counters["pairs"] =
      static_cast<double>(state.range(0)) * static_cast<double>(state.range(0) - 1) / 2.0;
}

// The peer: the loop a user writes (one thread, Eigen columns, running sums).
void BM_naive_sigma_l(benchmark::State& state) {
  const Data d = make_data(state.range(0));
  for (auto _ : state) {
    double sum = 0.0, sum_sq = 0.0;
    const Eigen::Index n = d.sensor.cols();
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = i + 1; j < n; ++j) {
        const double l = (d.sensor.col(i) - d.sensor.col(j)).norm() -
                         (d.robot.col(i) - d.robot.col(j)).norm();
        sum += l;
        sum_sq += l * l;
      }
    }
    const double pairs = static_cast<double>(n) * static_cast<double>(n - 1) / 2.0;
    benchmark::DoNotOptimize(std::sqrt((sum_sq - sum * sum / pairs) / (pairs - 1.0)));
  }
}

// The fastest repetition: on the shared machine the least disturbed run is the best estimate of
// the wall time on an idle one.
double fastest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

}  // namespace

BENCHMARK(BM_vrreg_register_rigid)->Arg(8)->Arg(1000)->Arg(9600)->Arg(1000000);
BENCHMARK(BM_vrreg_register_rigid_no_residuals)->Arg(8)->Arg(1000)->Arg(9600)->Arg(1000000);
BENCHMARK(BM_eigen_umeyama)->Arg(8)->Arg(1000)->Arg(9600)->Arg(1000000);
BENCHMARK(BM_vrreg_sigma_l)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->ComputeStatistics("min", fastest);
BENCHMARK(BM_naive_sigma_l)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
