// SPDX-License-Identifier: Apache-2.0
// A large cell: 47^3 = 103 823 fiducials on a 10 mm lattice (a smooth error field of a few tenths
// of a millimetre and 50 um noise per axis) fitted with each correction method, then 1 000
// targets inside corrected: Corrector::fit + correct, in memory (no file, no registration). The
// joint model needs a robot's joints: scripts/bench-large-cell.sh measures it, and every method
// through the command line with its peak memory; the scipy peers (RBFInterpolator with 50
// neighbours, Delaunay) are python/benchmarks/large_cell_peers.py (docs/benchmarks.md, "Large
// cells"). 5-35 s each: registered only when VRREG_BENCH_LARGE_CELL is set, so that a run without
// a filter stays quick.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdlib>

#include "vrreg/core/random.hpp"
#include "vrreg/correction/corrector.hpp"

namespace large_cell_bench {

using vrreg::InterpolationMethod;
using vrreg::Points3;

constexpr int kNodes = 47;
constexpr double kSpacingM = 0.01;
constexpr Eigen::Index kTargets = 1000;

const vrreg::CorrectorData& cell() {
  static const vrreg::CorrectorData data = [] {
    vrreg::Random rng(1);
    Points3 robot_m(3, static_cast<Eigen::Index>(kNodes) * kNodes * kNodes);
    Points3 corrections_m(3, robot_m.cols());
    Eigen::Index c = 0;
    for (int k = 0; k < kNodes; ++k)
      for (int j = 0; j < kNodes; ++j)
        for (int i = 0; i < kNodes; ++i, ++c) {
          const Eigen::Vector3d p = Eigen::Vector3d(0.2, -0.23, 0.02) + kSpacingM * Eigen::Vector3d(i, j, k);
          robot_m.col(c) = p;
          corrections_m.col(c) =
              2e-4 * Eigen::Vector3d(std::sin(8.0 * p.y()), std::cos(7.0 * p.z()), std::sin(9.0 * p.x())) +
              rng.normal3(5e-5);
        }
    vrreg::CorrectorData d = vrreg::CorrectorData::of(vrreg::SimilarityTransform{}, robot_m,
                                                      robot_m, corrections_m);
    d.noise_sd_m = 5e-5;
    return d;
  }();
  return data;
}

const Points3& targets() {
  static const Points3 points = [] {
    vrreg::Random rng(2);
    const Eigen::Vector3d lo = cell().fiducials_robot_m.rowwise().minCoeff().array() + kSpacingM;
    const Eigen::Vector3d hi = cell().fiducials_robot_m.rowwise().maxCoeff().array() - kSpacingM;
    Points3 p(3, kTargets);
    for (Eigen::Index j = 0; j < kTargets; ++j)
      for (int a = 0; a < 3; ++a) p(a, j) = rng.uniform(lo(a), hi(a));
    return p;
  }();
  return points;
}

const std::array<InterpolationMethod, 7> kMethods = {
    InterpolationMethod::kGrid,      InterpolationMethod::kScattered, InterpolationMethod::kOctuplet,
    InterpolationMethod::kTrilinear, InterpolationMethod::kKriging,   InterpolationMethod::kRbf,
    InterpolationMethod::kAuto};

// Corrector::fit on the 103 823 fiducials and correct() of the 1 000 targets.
void BM_large_cell_fit_correct(benchmark::State& state) {
  const InterpolationMethod method = kMethods[static_cast<std::size_t>(state.range(0))];
  (void)cell();
  (void)targets();
  vrreg::CorrectorOptions options;
  options.interpolation.method = method;
  if (method == InterpolationMethod::kOctuplet) options.interpolation.cube_edge_m = kSpacingM;
  // Octuplet asks each target's nominal position for its cube: the lattice cell's centre.
  Points3 nominal = targets();
  const Eigen::Vector3d origin_m = cell().fiducials_robot_m.rowwise().minCoeff();
  for (Eigen::Index j = 0; j < nominal.cols(); ++j) {
    for (int a = 0; a < 3; ++a)
      nominal(a, j) = origin_m(a) + kSpacingM * (std::floor((nominal(a, j) - origin_m(a)) / kSpacingM) + 0.5);
  }
  const Eigen::MatrixXd no_joints(0, 0);
  int flagged = 0;
  for (auto _ : state) {
    const vrreg::Corrector corrector = vrreg::Corrector::fit(cell(), options);
    const vrreg::TargetCorrection out =
        corrector.correct(vrreg::CorrectionQuery(targets(), nominal, no_joints));
    flagged = out.n_flagged;
    benchmark::DoNotOptimize(out.corrections_sensor_m.data());
  }
  state.SetLabel(std::string(vrreg::to_string(method)) + ", " + std::to_string(flagged) +
                 " of 1000 flagged");
}

[[maybe_unused]] const bool registered = [] {
  if (std::getenv("VRREG_BENCH_LARGE_CELL") == nullptr) return false;
  benchmark::RegisterBenchmark("BM_large_cell_fit_correct", BM_large_cell_fit_correct)
      ->DenseRange(0, static_cast<int>(kMethods.size()) - 1)
      ->Iterations(1)
      ->Unit(benchmark::kSecond)
      ->UseRealTime()
      ->MeasureProcessCPUTime();
  return true;
}();

}  // namespace large_cell_bench
