// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/testbed_calibration.hpp"

#include <chrono>
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/experiments/distance_sweep.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/planning/strategy2_labels.hpp"

namespace vrreg::experiments {
namespace {

using simulation::Dataset;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

RrbcRunOptions octuplet(double cube_edge_m, double sigma_rep_m) {
  RrbcRunOptions options;
  options.interpolation.method = InterpolationMethod::kOctuplet;
  options.interpolation.cube_edge_m = cube_edge_m;
  options.sigma_rep_m = sigma_rep_m;
  return options;
}

RrbcRunFigures run_grid_dataset(const simulation::Testbed& testbed, Dataset dataset,
                                std::uint64_t seed,
                                const std::optional<simulation::TestbedErrorModel>& errors,
                                double cube_edge_m) {
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, dataset, {seed, errors});
  const MeasurementSet set = to_measurement_set(data);
  return run_rrbc(set, set.select(Role::kFiducial), set.select(Role::kTarget),
                  octuplet(cube_edge_m, testbed.sigma_rep_spec_m));
}

// Dataset B (section 4.3): one registration from all 9600 fiducials; each target corrected from
// the eight corners of each of its ten cubes in turn (weights 1/8).
void run_b(const simulation::Testbed& testbed, std::uint64_t seed,
           const std::optional<simulation::TestbedErrorModel>& errors, Ur5SeedFigures& out) {
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, Dataset::kB, {seed, errors});
  const DistanceSweep sweep = run_distance_sweep(to_measurement_set(data), {});
  out.b_unc_rms_t_m = sweep.unc_rms_t_m;
  for (const SweepStep& step : sweep.steps) {
    out.b_cube_edge_m.push_back(step.cube_edge_m);
    out.b_cor_rms_t_m.push_back(step.cor_rms_t_m);
    out.b_n_bad.push_back(step.n_bad);
  }
}

std::array<RrbcRunFigures, 4> run_per_label(const MeasurementSet& set,
                                            const RrbcRunOptions& options) {
  std::array<RrbcRunFigures, 4> out;
  for (int m = 1; m <= 4; ++m) {
    out[static_cast<std::size_t>(m - 1)] =
        run_rrbc(set, set.select(Role::kFiducial, m), set.select(Role::kTarget, m), options);
  }
  return out;
}

}  // namespace

Ur5SeedFigures calibrate_ur5(const simulation::Testbed& testbed, std::uint64_t seed,
                             const std::optional<simulation::TestbedErrorModel>& errors) {
  const Clock::time_point start = Clock::now();
  Ur5SeedFigures f;
  f.seed = seed;
  f.a1 = run_grid_dataset(testbed, Dataset::kA1, seed, errors, 0.050);
  f.a2 = run_grid_dataset(testbed, Dataset::kA2, seed, errors, 0.025);
  run_b(testbed, seed, errors, f);
  f.seconds = seconds_since(start);
  return f;
}

Lwr4SeedFigures calibrate_lwr4(const simulation::Testbed& testbed, std::uint64_t seed,
                               const std::optional<simulation::TestbedErrorModel>& errors,
                               double sigma_opt_m) {
  const Clock::time_point start = Clock::now();
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, Dataset::kGrid, {seed, errors});
  const MeasurementSet set = to_measurement_set(data);
  RrbcRunOptions options = octuplet(0.040, testbed.sigma_rep_spec_m);
  options.sigma_opt_m = sigma_opt_m;
  Lwr4SeedFigures f;
  f.seed = seed;
  f.strategy1 = run_per_label(set, options);
  const planning::Strategy2Result ordered = planning::relabel_strategy2(set);
  f.switched_points_fraction = ordered.summary.switched_points_fraction();
  f.switched_locations_fraction = ordered.summary.switched_locations_fraction();
  f.strategy2 = run_per_label(ordered.set, options);
  f.seconds = seconds_since(start);
  return f;
}

CalibrationReport run_testbed_calibration(const CalibrationOptions& options) {
  VRREG_THROW_UNLESS(!options.seeds.empty(), "calibration: no seeds");
  CalibrationReport report;
  const simulation::Testbed ur5 = simulation::ur5_testbed();
  const simulation::Testbed lwr4 = simulation::lwr4_testbed();
  for (std::uint64_t seed : options.seeds) {
    double sigma_opt = lwr4.default_errors.tracker.noise_sigma_m.norm() / std::sqrt(3.0);
    if (options.lwr4_errors)
      sigma_opt = options.lwr4_errors->tracker.noise_sigma_m.norm() / std::sqrt(3.0);
    if (options.ur5) {
      report.ur5.push_back(calibrate_ur5(ur5, seed, options.ur5_errors));
      sigma_opt = report.ur5.back().a1.sigma_opt_m;
    }
    if (options.lwr4)
      report.lwr4.push_back(calibrate_lwr4(lwr4, seed, options.lwr4_errors, sigma_opt));
  }
  return report;
}

}  // namespace vrreg::experiments
