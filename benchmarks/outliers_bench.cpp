// SPDX-License-Identifier: Apache-2.0
// The robust check per fiducial set: leave-one-out prediction from neighbours
// (detect_outlier_fiducials, correction/outliers.hpp) beside the check it replaced, residuals
// against one rigid fit (register_rigid_robust), on a full n^3 lattice at 25 mm with a smooth
// field, noise and one displaced fiducial.
#include <benchmark/benchmark.h>

#include <cmath>

#include "vrreg/core/random.hpp"
#include "vrreg/correction/outliers.hpp"
#include "vrreg/registration/robust.hpp"

namespace {

using vrreg::Points3;

struct Cell {
  Points3 robot_m;
  Points3 sensor_m;
};

// n^3 nominal positions; sensor = robot + a smooth bend + noise, one fiducial 1 mm off.
Cell lattice_cell(int n) {
  vrreg::Random rng(3);
  Cell c;
  c.robot_m.resize(3, n * n * n);
  for (int k = 0, col = 0; k < n * n * n; ++k, ++col) {
    c.robot_m.col(col) = 0.025 * Eigen::Vector3d(k % n, (k / n) % n, k / (n * n));
  }
  c.sensor_m = c.robot_m;
  for (Eigen::Index j = 0; j < c.sensor_m.cols(); ++j) {
    const Eigen::Vector3d y = c.robot_m.col(j);
    c.sensor_m.col(j) += 1e-3 * Eigen::Vector3d(std::sin(8 * y.x()), std::cos(6 * y.y()), y.z()) +
                         rng.normal3(40e-6);
  }
  c.sensor_m.col(c.sensor_m.cols() / 2) += Eigen::Vector3d(1e-3, 0.0, 0.0);
  return c;
}

void BM_detect_outlier_fiducials(benchmark::State& state) {
  const Cell c = lattice_cell(static_cast<int>(state.range(0)));
  // eps = -X up to an affine field (outliers.hpp, step 1): enough for timing and verdicts.
  const Points3 eps = -c.sensor_m;
  for (auto _ : state) {
    benchmark::DoNotOptimize(vrreg::detect_outlier_fiducials(c.robot_m, eps, {}, 40e-6));
  }
  state.SetItemsProcessed(state.iterations() * c.robot_m.cols());
}
BENCHMARK(BM_detect_outlier_fiducials)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);

void BM_peer_register_rigid_robust(benchmark::State& state) {
  const Cell c = lattice_cell(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(vrreg::register_rigid_robust(c.sensor_m, c.robot_m));
  }
  state.SetItemsProcessed(state.iterations() * c.robot_m.cols());
}
BENCHMARK(BM_peer_register_rigid_robust)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace
