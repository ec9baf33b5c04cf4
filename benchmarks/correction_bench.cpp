// SPDX-License-Identifier: Apache-2.0
// RRBC target corrections (Eq. 7, 8) per second for 10^6 targets: grid (trilinear), scattered
// (Delaunay, barycentric) and octuplet, beside the peer a user might write instead: the 8 nearest
// fiducials (kd-tree) with inverse-distance weights. Interpolator build times are separate.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <nanoflann.hpp>
#include <vector>

#include "vrreg/core/random.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/grid.hpp"
#include "vrreg/correction/octuplet.hpp"
#include "vrreg/correction/scattered.hpp"

namespace {

using vrreg::Points3;

constexpr Eigen::Index kTargets = 1'000'000;

/// Dataset A1 (range 0: 11 x 13 x 9 at 25 mm, 1167 fiducials) or A2 (range 1: 21 x 25 x 17 at
/// 12.5 mm, 7965 fiducials) in the robot frame: the full grid minus the all-odd nodes (targets).
Points3 a_fiducials(int which) {
  const int nx = which == 0 ? 11 : 21;
  const int ny = which == 0 ? 13 : 25;
  const int nz = which == 0 ? 9 : 17;
  const double h = 0.25 / (nx - 1);
  Points3 out(3, nx * ny * nz);
  Eigen::Index c = 0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        if (i % 2 == 1 && j % 2 == 1 && k % 2 == 1) continue;
        out.col(c++) = Eigen::Vector3d(0.3 + h * i, -0.15 + h * j, 0.05 + h * k);
      }
    }
  }
  return out.leftCols(c);
}

/// Random scattered fiducials in the same 250 x 300 x 200 mm volume.
Points3 scattered_fiducials(Eigen::Index n) {
  vrreg::Random rng(71);
  Points3 out(3, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    out.col(j) =
        Eigen::Vector3d(rng.uniform(0.3, 0.55), rng.uniform(-0.15, 0.15), rng.uniform(0.05, 0.25));
  }
  return out;
}

vrreg::RigidTransform sensor_pose() {
  vrreg::Random rng(73);
  vrreg::RigidTransform T;
  T.rotation = rng.rotation();
  T.translation_m = Eigen::Vector3d(1.1, -0.3, 2.0);
  return T;
}

/// A correction field over the fiducials with mm-scale corrections.
vrreg::CorrectionField make_model(const Points3& fiducials_robot_m) {
  vrreg::CorrectionField model;
  model.T_robot_sensor = sensor_pose();
  model.fiducials_robot_m = fiducials_robot_m;
  vrreg::Random rng(79);
  model.corrections_sensor_m.resize(3, fiducials_robot_m.cols());
  for (Eigen::Index j = 0; j < fiducials_robot_m.cols(); ++j) {
    model.corrections_sensor_m.col(j) = rng.normal3(0.5e-3);
  }
  return model;
}

/// Targets inside the (inner) volume: registered positions [m, robot] and sensor positions.
struct Targets {
  Points3 robot_m;
  Points3 sensor_m;
};
Targets make_targets(Eigen::Index n) {
  vrreg::Random rng(83);
  Targets t{Points3(3, n), Points3(3, n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    t.robot_m.col(i) =
        Eigen::Vector3d(rng.uniform(0.31, 0.54), rng.uniform(-0.14, 0.14), rng.uniform(0.06, 0.24));
  }
  t.sensor_m = sensor_pose().inverse().apply_all(t.robot_m);
  return t;
}

const Targets& targets() {
  static const Targets t = make_targets(kTargets);
  return t;
}

void BM_build_grid(benchmark::State& state) {
  const Points3 f = a_fiducials(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(vrreg::detect_grid(f, 1e-6));
  state.counters["fiducials"] = static_cast<double>(f.cols());
}
BENCHMARK(BM_build_grid)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_build_scattered(benchmark::State& state) {
  const Points3 f = state.range(0) < 2 ? a_fiducials(static_cast<int>(state.range(0)))
                                       : scattered_fiducials(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(vrreg::ScatteredStencils(f, 1e-6));
  state.counters["fiducials"] = static_cast<double>(f.cols());
}
BENCHMARK(BM_build_scattered)->Arg(0)->Arg(1)->Arg(10000)->Unit(benchmark::kMillisecond);

/// Stencils and Eq. 7 only, one thread, 10^6 targets.
void BM_stencils_grid(benchmark::State& state) {
  const Points3 f = a_fiducials(static_cast<int>(state.range(0)));
  const vrreg::GridLayout grid = *vrreg::detect_grid(f, 1e-6).grid;
  const Points3 eps = make_model(f).corrections_sensor_m;
  for (auto _ : state) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (Eigen::Index i = 0; i < kTargets; ++i) {
      sum += vrreg::interpolate_correction(
          vrreg::grid_stencil(grid, targets().robot_m.col(i), 1e-6), eps);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kTargets);
}
BENCHMARK(BM_stencils_grid)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_stencils_scattered(benchmark::State& state) {
  const Points3 f = state.range(0) < 2 ? a_fiducials(static_cast<int>(state.range(0)))
                                       : scattered_fiducials(state.range(0));
  const vrreg::ScatteredStencils stencils(f, 1e-6);
  const Points3 eps = make_model(f).corrections_sensor_m;
  std::int64_t steps = 0;
  std::int64_t fallbacks = 0;
  for (auto _ : state) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (Eigen::Index i = 0; i < kTargets; ++i) {
      vrreg::LocateStats stats;
      const vrreg::Stencil s = stencils.stencil(targets().robot_m.col(i), &stats);
      steps += stats.steps;
      fallbacks += stats.fallback ? 1 : 0;
      if (s.status == vrreg::StencilStatus::kOk) sum += vrreg::interpolate_correction(s, eps);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kTargets);
  const auto located = static_cast<double>(state.iterations() * kTargets);
  state.counters["walk_steps"] = static_cast<double>(steps) / located;
  state.counters["fallbacks"] = static_cast<double>(fallbacks) / located;
}
BENCHMARK(BM_stencils_scattered)->Arg(0)->Arg(1)->Arg(10000)->Unit(benchmark::kMillisecond);

/// The peer: the 8 nearest fiducials (nanoflann kd-tree) with inverse-distance weights. No
/// linear precision and no outside flag, but it is what one writes in ten lines.
struct Cloud {
  const Points3* points;
  [[nodiscard]] std::size_t kdtree_get_point_count() const {
    return static_cast<std::size_t>(points->cols());
  }
  [[nodiscard]] double kdtree_get_pt(std::size_t i, std::size_t d) const {
    return (*points)(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(i));
  }
  template <class B>
  bool kdtree_get_bbox(B&) const {
    return false;
  }
};
using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud,
                                                 3, std::size_t>;

void BM_peer_nearest8_idw(benchmark::State& state) {
  const Points3 f = state.range(0) < 2 ? a_fiducials(static_cast<int>(state.range(0)))
                                       : scattered_fiducials(state.range(0));
  const Cloud cloud{&f};
  Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  const Points3 eps = make_model(f).corrections_sensor_m;
  for (auto _ : state) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (Eigen::Index i = 0; i < kTargets; ++i) {
      std::array<std::size_t, 8> index{};
      std::array<double, 8> d2{};
      const Eigen::Vector3d q = targets().robot_m.col(i);
      tree.knnSearch(q.data(), 8, index.data(), d2.data());
      Eigen::Vector3d num = Eigen::Vector3d::Zero();
      double den = 0.0;
      for (std::size_t k = 0; k < 8; ++k) {
        const double w = 1.0 / std::max(std::sqrt(d2[k]), 1e-12);
        num += w * eps.col(static_cast<Eigen::Index>(index[k]));
        den += w;
      }
      sum += num / den;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kTargets);
}
BENCHMARK(BM_peer_nearest8_idw)->Arg(0)->Arg(1)->Arg(10000)->Unit(benchmark::kMillisecond);

/// The whole of correct_targets (build + stencils + Eq. 7, 8 + mapping, TBB over targets).
void correct_all(benchmark::State& state, vrreg::InterpolationMethod method) {
  const Points3 f = a_fiducials(static_cast<int>(state.range(0)));
  const vrreg::CorrectionField model = make_model(f);
  vrreg::InterpolationSettings settings;
  settings.method = method;
  settings.cube_edge_m = state.range(0) == 0 ? 0.05 : 0.025;
  // Octuplet: targets at the nominal A-dataset target positions (cube centres), cycled to 10^6.
  Points3 nominal(3, method == vrreg::InterpolationMethod::kOctuplet ? kTargets : 0);
  if (nominal.cols() > 0) {
    const double h = settings.cube_edge_m / 2;
    const int nx = state.range(0) == 0 ? 5 : 10;
    const int ny = state.range(0) == 0 ? 6 : 12;
    const int nz = state.range(0) == 0 ? 4 : 8;
    for (Eigen::Index i = 0; i < kTargets; ++i) {
      const auto c = static_cast<int>(i % (nx * ny * nz));
      nominal.col(i) =
          Eigen::Vector3d(0.3 + h * (2 * (c % nx) + 1), -0.15 + h * (2 * ((c / nx) % ny) + 1),
                          0.05 + h * (2 * (c / (nx * ny)) + 1));
    }
  }
  int flagged = 0;
  for (auto _ : state) {
    const vrreg::TargetCorrection c =
        vrreg::correct_targets(model, targets().sensor_m, nominal, settings);
    flagged = c.n_flagged;
    benchmark::DoNotOptimize(c.corrected_robot_m.data());
  }
  state.SetItemsProcessed(state.iterations() * kTargets);
  state.counters["flagged"] = flagged;
}
void BM_correct_targets_grid(benchmark::State& s) {
  correct_all(s, vrreg::InterpolationMethod::kGrid);
}
void BM_correct_targets_scattered(benchmark::State& s) {
  correct_all(s, vrreg::InterpolationMethod::kScattered);
}
void BM_correct_targets_octuplet(benchmark::State& s) {
  correct_all(s, vrreg::InterpolationMethod::kOctuplet);
}
// Process CPU time (all threads) beside wall time: on a shared machine the wall time of a
// 2-thread run says little, the CPU seconds say what the work costs.
BENCHMARK(BM_correct_targets_grid)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->ComputeStatistics("min", [](const std::vector<double>& v) {  // least disturbed run
      return *std::min_element(v.begin(), v.end());
    });
BENCHMARK(BM_correct_targets_scattered)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_correct_targets_octuplet)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
