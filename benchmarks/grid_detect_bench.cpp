// SPDX-License-Identifier: Apache-2.0
// Grid detection (detect_grid, the first step of the default interpolation) on 10^3-10^5
// fiducials: uniform random positions written with 3-6 decimals in mm, as a cell measured at free
// positions is; full, holed (A1-like, and random holes), jittered and rotated lattices.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "vrreg/core/random.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/grid.hpp"

namespace {

using vrreg::Points3;

constexpr double kTolerance = 1e-6;  // the default match tolerance [m]

/// x_mm as a CSV holding it with `decimals` digits after the point gives it back, in metres.
double written_mm(double x_mm, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, x_mm);
  return vrreg::units::mm_to_m(std::strtod(text, nullptr));
}

/// n points uniform in the paper's 250 x 300 x 200 mm volume, each written with 3-6 decimals.
Points3 random_written(Eigen::Index n) {
  vrreg::Random rng(101);
  Points3 out(3, n);
  const double lo[3] = {300.0, -150.0, 50.0};
  const double size[3] = {250.0, 300.0, 200.0};
  for (Eigen::Index j = 0; j < n; ++j) {
    const int decimals = 3 + static_cast<int>(rng.below(4));
    for (int a = 0; a < 3; ++a) out(a, j) = written_mm(lo[a] + size[a] * rng.uniform(), decimals);
  }
  return out;
}

/// About n nodes of a cube lattice at 10 mm; `keep(i, j, k)` picks the nodes that are fiducials.
template <class Keep>
Points3 lattice(Eigen::Index n, Keep keep) {
  const int side = static_cast<int>(std::lround(std::cbrt(static_cast<double>(n))));
  Points3 out(3, static_cast<Eigen::Index>(side) * side * side);
  Eigen::Index c = 0;
  for (int k = 0; k < side; ++k) {
    for (int j = 0; j < side; ++j) {
      for (int i = 0; i < side; ++i) {
        if (keep(i, j, k))
          out.col(c++) = Eigen::Vector3d(0.3, -0.15, 0.05) + 0.01 * Eigen::Vector3d(i, j, k);
      }
    }
  }
  return out.leftCols(c);
}

/// 10^3, 10^4 and 10^5 fiducials.
void sizes(benchmark::internal::Benchmark* b) {
  b->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
}

void run(benchmark::State& state, const Points3& fiducials, bool expect_grid) {
  const vrreg::GridDetection first = vrreg::detect_grid(fiducials, kTolerance);
  if (first.grid.has_value() != expect_grid) {
    state.SkipWithError(("unexpected detection: " + first.reason).c_str());
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(vrreg::detect_grid(fiducials, kTolerance));
  state.counters["fiducials"] = static_cast<double>(fiducials.cols());
}

void BM_detect_grid_random(benchmark::State& state) {
  run(state, random_written(state.range(0)), false);
}
BENCHMARK(BM_detect_grid_random)->Arg(700)->Apply(sizes);

void BM_detect_grid_full_lattice(benchmark::State& state) {
  run(state, lattice(state.range(0), [](int, int, int) { return true; }), true);
}
BENCHMARK(BM_detect_grid_full_lattice)->Apply(sizes);

/// The A1 pattern: the all-odd nodes are targets, the rest hold the every-2nd sub-lattice.
void BM_detect_grid_a1_pattern(benchmark::State& state) {
  run(state, lattice(state.range(0), [](int i, int j, int k) { return (i & j & k & 1) == 0; }),
      true);
}
BENCHMARK(BM_detect_grid_a1_pattern)->Apply(sizes);

/// 10 % of the nodes missing at random: the search runs through the strides to a complete one.
void BM_detect_grid_random_holes(benchmark::State& state) {
  vrreg::Random rng(103);
  const Points3 f = lattice(state.range(0), [&](int, int, int) { return rng.uniform() >= 0.1; });
  const vrreg::GridDetection d = vrreg::detect_grid(f, kTolerance);
  for (auto _ : state) benchmark::DoNotOptimize(vrreg::detect_grid(f, kTolerance));
  state.counters["fiducials"] = static_cast<double>(f.cols());
  state.counters["stride"] = d.grid ? d.grid->stride : 0;
}
BENCHMARK(BM_detect_grid_random_holes)->Apply(sizes);

/// Every node moved by up to 1 mm per axis (1000 tolerances): not a grid.
void BM_detect_grid_jittered(benchmark::State& state) {
  vrreg::Random rng(107);
  Points3 f = lattice(state.range(0), [](int, int, int) { return true; });
  for (Eigen::Index j = 0; j < f.cols(); ++j) {
    for (int a = 0; a < 3; ++a) f(a, j) += rng.uniform(-1e-3, 1e-3);
  }
  run(state, f, false);
}
BENCHMARK(BM_detect_grid_jittered)->Apply(sizes);

/// A full lattice in a random orientation: not an axis-aligned grid.
void BM_detect_grid_rotated(benchmark::State& state) {
  vrreg::Random rng(109);
  const Points3 f = rng.rotation() * lattice(state.range(0), [](int, int, int) { return true; });
  run(state, f, false);
}
BENCHMARK(BM_detect_grid_rotated)->Apply(sizes);

}  // namespace
