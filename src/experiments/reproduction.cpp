// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/reproduction.hpp"

#include <cmath>

#include "parallel_tasks.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::experiments {
namespace {

using simulation::Dataset;

MeasurementSet simulate(const simulation::Testbed& testbed, Dataset dataset, std::uint64_t seed,
                        const std::optional<simulation::TestbedErrorModel>& errors) {
  return to_measurement_set(simulation::simulate_dataset(testbed, dataset, {seed, errors}));
}

void step(const std::function<void()>& on_step) {
  if (on_step) on_step();
}

void run_ur5(const ReproductionOptions& o, const std::function<void()>& on_step,
             Reproduction& out) {
  const simulation::Testbed ur5 = simulation::ur5_testbed();
  Table1Options t1;
  t1.sigma_rep_m = ur5.sigma_rep_spec_m;
  t1.l_histogram_bin_m = o.l_histogram_bin_m;
  t1.cube_edge_m = 0.050;
  out.a1 = run_table1_entry(simulate(ur5, Dataset::kA1, o.seed, o.ur5_errors), "A1", t1);
  step(on_step);
  t1.cube_edge_m = 0.025;
  out.a2 = run_table1_entry(simulate(ur5, Dataset::kA2, o.seed, o.ur5_errors), "A2", t1);
  step(on_step);
  DistanceSweepOptions sweep;
  sweep.delta_tre_bin_m = o.delta_tre_bin_m;
  out.b = run_distance_sweep(simulate(ur5, Dataset::kB, o.seed, o.ur5_errors), sweep);
  step(on_step);
}

void run_lwr4(const ReproductionOptions& o, const std::function<void()>& on_step,
              Reproduction& out) {
  const simulation::Testbed lwr4 = simulation::lwr4_testbed();
  Table2Options t2;
  t2.sigma_rep_m = lwr4.sigma_rep_spec_m;
  if (out.a1) {
    t2.sigma_opt_m = out.a1->figures.sigma_opt_m;
  } else {
    const simulation::TrackerModel& tracker = o.lwr4_errors.value_or(lwr4.default_errors).tracker;
    t2.sigma_opt_m = tracker.noise_sigma_m.norm() / std::sqrt(3.0);
  }
  t2.strategy3_seed = o.seed;
  t2.l_histogram_bin_m = o.l_histogram_bin_m;
  out.table2 = run_table2(simulate(lwr4, Dataset::kGrid, o.seed, o.lwr4_errors), t2);
  step(on_step);
}

BeyondOptions beyond_options(const ReproductionOptions& o) {
  return {o.seed, o.ur5, o.lwr4, o.ur5_errors, o.lwr4_errors, {}};
}

}  // namespace

void ReproductionOptions::validate() const {
  VRREG_THROW_UNLESS(ur5 || lwr4, "reproduce: nothing to run (neither the UR5 nor the KUKA)");
  VRREG_THROW_UNLESS(std::isfinite(l_histogram_bin_m) && l_histogram_bin_m > 0.0,
                     "reproduce: the L histogram bin must be > 0, got " << l_histogram_bin_m);
  VRREG_THROW_UNLESS(std::isfinite(delta_tre_bin_m) && delta_tre_bin_m > 0.0,
                     "reproduce: the Delta TRE bin must be > 0, got " << delta_tre_bin_m);
}

int reproduction_steps(const ReproductionOptions& options) {
  const int beyond = options.beyond ? beyond_steps(beyond_options(options)) : 0;
  return (options.ur5 ? 3 : 0) + (options.lwr4 ? 1 : 0) + beyond;
}

Reproduction run_reproduction(const ReproductionOptions& options,
                              const std::function<void()>& on_step) {
  options.validate();
  Reproduction out;
  out.seed = options.seed;
  if (options.ur5) run_ur5(options, on_step, out);
  if (options.lwr4) run_lwr4(options, on_step, out);
  if (options.beyond) out.beyond = run_beyond_paper(beyond_options(options), on_step);
  return out;
}

std::vector<Reproduction> run_reproductions(const std::vector<std::uint64_t>& seeds,
                                            const ReproductionOptions& options,
                                            const std::function<void()>& on_step) {
  options.validate();
  std::vector<Reproduction> out(seeds.size());
  detail::parallel_tasks(seeds.size(), [&](std::size_t k) {
    ReproductionOptions one = options;
    one.seed = seeds[k];
    out[k] = run_reproduction(one, on_step);
  });
  return out;
}

}  // namespace vrreg::experiments
