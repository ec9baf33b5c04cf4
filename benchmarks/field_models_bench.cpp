// SPDX-License-Identifier: Apache-2.0
// Field models (kriging, RBF) fitted to the fiducials of A1 (1 167) and A2 (7 965) and
// predicted at the targets: time of fit + predict, RMS against the true field, and the
// calibration of kriging's predicted sd. The peers (scikit-learn GaussianProcessRegressor,
// scipy RBFInterpolator) run on the same data in scripts/bench-field-peers.py, which sets
// VRREG_FIELD_DATA_DIR so that this binary writes the data as CSV (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include "vrreg/core/random.hpp"
#include "vrreg/correction/kriging.hpp"
#include "vrreg/correction/rbf.hpp"

namespace {

using vrreg::Points3;

/// Noise of one fiducial value per axis [m] (3D RMS 0.087 mm, like the simulated cells).
constexpr double kNoiseSdM = 50e-6;

struct FieldData {
  Points3 fiducials_m;
  Points3 values_m;   ///< true field + noise at the fiducials
  Points3 targets_m;
  Points3 truth_m;    ///< true field at the targets
};

/// A smooth correction field of a few tenths of a millimetre: quadratic + two waves per axis.
Eigen::Vector3d true_field_m(const Eigen::Vector3d& p_m) {
  const Eigen::Vector3d u = (p_m - Eigen::Vector3d(0.425, -0.025, 0.15)) / 0.25;
  const double two_pi = 2.0 * M_PI;
  return 1e-3 * Eigen::Vector3d(
                    0.3 * u.x() * u.x() - 0.2 * u.y() * u.z() + 0.1 * u.x() +
                        0.15 * std::sin(two_pi * (0.8 * u.x() + 1.1 * u.y()) + 0.3) +
                        0.10 * std::cos(two_pi * (1.3 * u.z() - 0.5 * u.x())),
                    -0.2 * u.y() * u.y() + 0.25 * u.x() * u.z() - 0.1 * u.z() +
                        0.12 * std::sin(two_pi * (1.2 * u.z() + 0.6 * u.y()) + 1.1) +
                        0.10 * std::cos(two_pi * (0.9 * u.x() - 1.0 * u.z())),
                    0.25 * u.z() * u.z() + 0.15 * u.x() * u.y() + 0.05 * u.y() +
                        0.15 * std::sin(two_pi * (1.0 * u.y() - 0.7 * u.z()) + 2.0) +
                        0.08 * std::cos(two_pi * (1.4 * u.x() + 0.4 * u.y())));
}

/// A1 (which = 0: 11 x 13 x 9 at 25 mm) or A2 (which = 1: 21 x 25 x 17 at 12.5 mm): the
/// all-odd nodes are targets, the others fiducials with noisy field values (seed 12).
FieldData field_data(int which) {
  const int nx = which == 0 ? 11 : 21;
  const int ny = which == 0 ? 13 : 25;
  const int nz = which == 0 ? 9 : 17;
  const double h_m = 0.25 / (nx - 1);
  FieldData d{Points3(3, nx * ny * nz), Points3(3, nx * ny * nz), Points3(3, nx * ny * nz),
              Points3(3, nx * ny * nz)};
  vrreg::Random rng(12);
  Eigen::Index nf = 0;
  Eigen::Index nt = 0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const Eigen::Vector3d p(0.3 + h_m * i, -0.15 + h_m * j, 0.05 + h_m * k);
        if (i % 2 == 1 && j % 2 == 1 && k % 2 == 1) {
          d.targets_m.col(nt) = p;
          d.truth_m.col(nt++) = true_field_m(p);
        } else {
          d.fiducials_m.col(nf) = p;
          d.values_m.col(nf++) = true_field_m(p) + rng.normal3(kNoiseSdM);
        }
      }
    }
  }
  d.fiducials_m.conservativeResize(3, nf);
  d.values_m.conservativeResize(3, nf);
  d.targets_m.conservativeResize(3, nt);
  d.truth_m.conservativeResize(3, nt);
  return d;
}

void write_csv(const std::string& path, const Points3& a, const Points3& b) {
  std::ofstream out(path);
  out.precision(17);
  out << "x,y,z,vx,vy,vz\n";
  for (Eigen::Index j = 0; j < a.cols(); ++j) {
    out << a(0, j) << ',' << a(1, j) << ',' << a(2, j) << ',' << b(0, j) << ',' << b(1, j)
        << ',' << b(2, j) << '\n';
  }
}

/// The data of `which`, written once as CSV when VRREG_FIELD_DATA_DIR is set.
const FieldData& data_for(int which) {
  static const FieldData a1 = field_data(0);
  static const FieldData a2 = field_data(1);
  const FieldData& d = which == 0 ? a1 : a2;
  if (const char* dir = std::getenv("VRREG_FIELD_DATA_DIR")) {
    const std::string name = std::string(dir) + (which == 0 ? "/a1" : "/a2");
    write_csv(name + "_fiducials.csv", d.fiducials_m, d.values_m);
    write_csv(name + "_targets.csv", d.targets_m, d.truth_m);
  }
  return d;
}

/// 3D RMS of the prediction error [m].
double rms_3d(const Points3& predicted, const Points3& truth) {
  return std::sqrt((predicted - truth).colwise().squaredNorm().mean());
}

void BM_FieldKriging(benchmark::State& state) {
  const FieldData& d = data_for(static_cast<int>(state.range(0)));
  vrreg::KrigingOptions options;
  options.fit_subset = state.range(1);
  options.exact_limit = state.range(2);
  options.restarts = static_cast<int>(state.range(3));
  vrreg::FieldPrediction p;
  int evaluations = 0;
  for (auto _ : state) {
    const vrreg::KrigingModel model = vrreg::KrigingModel::fit(d.fiducials_m, d.values_m, options);
    p = model.predict(d.targets_m);
    benchmark::DoNotOptimize(p.mean_m.data());
    evaluations = model.axes()[0].evaluations + model.axes()[1].evaluations +
                  model.axes()[2].evaluations;
  }
  state.counters["evaluations"] = evaluations;
  state.counters["fiducials"] = static_cast<double>(d.fiducials_m.cols());
  state.counters["rms_um"] = 1e6 * rms_3d(p.mean_m, d.truth_m);
  state.counters["z_rms"] =
      std::sqrt((p.mean_m - d.truth_m).cwiseQuotient(p.sd_m).array().square().mean());
}
// Arguments: dataset (0 = A1, 1 = A2), fit subset, exact limit, restarts; the defaults first.
BENCHMARK(BM_FieldKriging)
    ->Args({0, 500, 2000, 2})
    ->Args({1, 500, 2000, 2})
    ->Args({0, 1167, 2000, 1})
    ->Args({0, 500, 500, 2})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_FieldRbf(benchmark::State& state) {
  const FieldData& d = data_for(static_cast<int>(state.range(0)));
  vrreg::FieldPrediction p;
  for (auto _ : state) {
    const vrreg::RbfModel model = vrreg::RbfModel::fit(d.fiducials_m, d.values_m);
    p = model.predict(d.targets_m);
    benchmark::DoNotOptimize(p.mean_m.data());
  }
  state.counters["fiducials"] = static_cast<double>(d.fiducials_m.cols());
  state.counters["rms_um"] = 1e6 * rms_3d(p.mean_m, d.truth_m);
}
BENCHMARK(BM_FieldRbf)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

}  // namespace
