// SPDX-License-Identifier: Apache-2.0
// Beyond the paper: the datasets of the table (docs/reproduction.md, "Beyond the paper"), each
// simulated twice with the same seed — as measured and without noise, for the noise floor.
#include "vrreg/experiments/beyond_paper.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <set>

#include "vrreg/core/check.hpp"
#include "vrreg/experiments/distance_sweep.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/experiments/table2.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::experiments {
namespace {

using simulation::Dataset;

// A dataset as measured and its noise-free twin (same seed, same robot, same visits).
struct Twin {
  MeasurementSet measured;
  MeasurementSet noise_free;
};

Twin simulate_twin(const simulation::Testbed& testbed, Dataset dataset, std::uint64_t seed,
                   const std::optional<simulation::TestbedErrorModel>& errors,
                   double rigid_body_radius_m) {
  simulation::TestbedErrorModel e = testbed.default_errors;
  e.tracker.rigid_body_radius_m = rigid_body_radius_m;  // the positions' draws stay the same
  if (errors) e = *errors;
  return {to_measurement_set(simulation::simulate_dataset(testbed, dataset, {seed, e})),
          to_measurement_set(simulation::simulate_dataset(testbed, dataset, {seed, without_noise(e)}))};
}

void beyond_step(const std::function<void()>& on_step) {
  if (on_step) on_step();
}

std::vector<std::size_t> all_positions(const MeasurementSet& set) {
  std::vector<std::size_t> out(set.select(Role::kTarget).size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = k;
  return out;
}

void append(std::vector<BeyondTable>& out, std::vector<BeyondTable> more) {
  for (BeyondTable& t : more) out.push_back(std::move(t));
}

// The grid node of an A1 label "pII_JJ_KK" (simulation/dataset_plan.cpp).
Eigen::Vector3i node_of(const std::string& point) {
  Eigen::Vector3i n;
  VRREG_THROW_UNLESS(std::sscanf(point.c_str(), "p%d_%d_%d", &n.x(), &n.y(), &n.z()) == 3,
                     "beyond the paper: '" << point << "' is not a grid label");
  return n;
}

// The locations of `set` whose grid node passes `keep`, in set order.
template <typename Keep>
MeasurementSet subset(const MeasurementSet& set, const std::string& what, Keep keep) {
  MeasurementSet out = set;
  out.source = set.source + " " + what;
  out.locations.clear();
  for (const Location& loc : set.locations) {
    if (keep(node_of(loc.point), loc.role)) out.locations.push_back(loc);
  }
  return out;
}

template <typename Keep>
Twin subset(const Twin& twin, const std::string& what, Keep keep) {
  return {subset(twin.measured, what, keep), subset(twin.noise_free, what, keep)};
}

// B's corners shared by neighbouring targets' cubes are measured more than once; a field model
// takes one correction per position, so each keeps its first reading (visiting order).
MeasurementSet first_readings(const MeasurementSet& set) {
  MeasurementSet out = set;
  out.locations.clear();
  std::set<std::array<long long, 3>> seen;
  for (const Location& loc : set.locations) {
    const std::array<long long, 3> um = {std::llround(1e6 * loc.robot_m.x()),
                                         std::llround(1e6 * loc.robot_m.y()),
                                         std::llround(1e6 * loc.robot_m.z())};
    if (loc.role == Role::kTarget || seen.insert(um).second) out.locations.push_back(loc);
  }
  return out;
}

// The lost-motion cells: A1's half with x <= 125 mm, positions only (two A1-sized cells would
// double the run's time).
void beyond_lost_motion(const BeyondOptions& o, const simulation::Testbed& ur5,
                        std::vector<BeyondTable>& out) {
  const double a1_step_m = simulation::grid_spec(Dataset::kA1).step_m;
  simulation::TestbedErrorModel base = o.ur5_errors.value_or(ur5.default_errors);
  base.tracker.rigid_body_radius_m = 0.0;
  for (const bool mixed : {false, true}) {
    const Twin full = simulate_twin(ur5, Dataset::kA1, o.seed, lost_motion_errors(base, mixed), 0.0);
    // Targets with every octuplet corner inside the half (the paper's row applies to all).
    const Twin half = subset(full, "x <= 125 mm", [](const Eigen::Vector3i& n, Role r) {
      return n.x() <= (r == Role::kTarget ? 4 : 5);
    });
    const std::string key = mixed ? "A1_mixed" : "A1_backlash";
    const std::string what = mixed ? "A1 half, lost motion + gravity + thermal"
                                   : "A1 half, lost motion (backlash)";
    append(out, beyond_tables(half.measured, half.noise_free, ur5.nominal, ur5.sigma_rep_spec_m,
                              {{key, what, all_positions(half.measured)}}, 2.0 * a1_step_m,
                              o.methods));
  }
}

bool all_even(const Eigen::Vector3i& n) { return n.x() % 2 == 0 && n.y() % 2 == 0 && n.z() % 2 == 0; }

void beyond_ur5(const BeyondOptions& o, const std::function<void()>& on_step,
             std::vector<BeyondTable>& out) {
  const simulation::Testbed ur5 = simulation::ur5_testbed();
  const double rep = ur5.sigma_rep_spec_m;
  const auto tables = [&](const Twin& t, const std::string& key, const std::string& what,
                          std::optional<double> octuplet) {
    return beyond_tables(t.measured, t.noise_free, ur5.nominal, rep,
                         {{key, what, all_positions(t.measured)}}, octuplet, o.methods);
  };
  const double a1_step_m = simulation::grid_spec(Dataset::kA1).step_m;
  const Twin a1 = simulate_twin(ur5, Dataset::kA1, o.seed, o.ur5_errors, o.rigid_body_radius_m);
  append(out, tables(a1, "A1", "A1: all fiducials, octuplet a = 50 mm", 2.0 * a1_step_m));
  // Fewer fiducials: the octuplet corners only (every second node, 50 mm apart); the targets
  // stay at the centres of those cubes, so the paper's octuplet still applies.
  const Twin thin = subset(a1, "thinned", [](const Eigen::Vector3i& n, Role r) {
    return r == Role::kTarget || all_even(n);
  });
  append(out, tables(thin, "A1_thinned", "A1, every second node (50 mm)", 2.0 * a1_step_m));
  // 27 fiducials: the 3 x 3 x 3 even nodes (50 mm apart, a 100 mm cube) around node p04_06_04,
  // the even node nearest the volume centre; targets: the 8 A1 targets inside that cube.
  const Eigen::Vector3i centre(4, 6, 4);
  const Twin cube = subset(a1, "cube27", [&centre](const Eigen::Vector3i& n, Role r) {
    const Eigen::Vector3i d = (n - centre).cwiseAbs();
    if (r == Role::kTarget) return d.maxCoeff() <= 1;
    return all_even(n) && d.maxCoeff() <= 2;
  });
  append(out, tables(cube, "A1_cube27", "A1, 27 fiducials around p04_06_04", 2.0 * a1_step_m));
  beyond_step(on_step);
  if (o.lost_motion) {
    beyond_lost_motion(o, ur5, out);
    beyond_step(on_step);
  }

  const Twin a2 = simulate_twin(ur5, Dataset::kA2, o.seed, o.ur5_errors, 0.0);
  append(out, tables(a2, "A2", "A2: all fiducials, octuplet a = 25 mm",
                     2.0 * simulation::grid_spec(Dataset::kA2).step_m));
  beyond_step(on_step);

  // B: the paper's row is its best, the smallest octuplet (d_min), with its visiting-order rule
  // for corners measured twice.
  const Twin b = simulate_twin(ur5, Dataset::kB, o.seed, o.ur5_errors, 0.0);
  const Twin b_once{first_readings(b.measured), first_readings(b.noise_free)};
  std::vector<BeyondTable> tb =
      tables(b_once, "B", "B: every cube corner once, octuplet a = 5 mm", {});
  DistanceSweepOptions smallest;
  smallest.cube_edges_m = {dataset_b_cube_edges_m().back()};
  const DistanceSweep sweep = run_distance_sweep(b.measured, smallest);
  BeyondRow paper;
  paper.method = "octuplet";
  paper.ok = true;
  paper.cor_rms_t_m = sweep.steps.front().cor_rms_t_m;
  tb.front().rows.insert(tb.front().rows.begin(), paper);
  append(out, std::move(tb));
  beyond_step(on_step);
}

// KUKA: one model over every configuration's fiducials, targets reported per configuration (as
// the IK listed them); the paper's rows are Table 2's Strategies 2 and 3.
void beyond_lwr4(const BeyondOptions& o, const std::function<void()>& on_step,
              std::vector<BeyondTable>& out) {
  const simulation::Testbed lwr4 = simulation::lwr4_testbed();
  const Twin grid =
      simulate_twin(lwr4, Dataset::kGrid, o.seed, o.lwr4_errors, o.rigid_body_radius_m);
  const std::vector<std::size_t> targets = grid.measured.select(Role::kTarget);
  std::set<int> configs;
  for (const std::size_t i : targets) configs.insert(grid.measured.locations[i].config.value_or(0));
  std::vector<TargetGroup> groups;
  for (const int m : configs) {
    TargetGroup g{"kuka_" + std::to_string(m), "KUKA configuration " + std::to_string(m), {}};
    for (std::size_t k = 0; k < targets.size(); ++k) {
      if (grid.measured.locations[targets[k]].config == m) g.positions.push_back(k);
    }
    groups.push_back(std::move(g));
  }
  std::vector<BeyondTable> tables = beyond_tables(grid.measured, grid.noise_free, lwr4.nominal,
                                                  lwr4.sigma_rep_spec_m, groups, {}, o.methods);
  Table2Options t2;
  t2.sigma_rep_m = lwr4.sigma_rep_spec_m;
  t2.strategy3_seed = o.seed;
  const Table2 paper = run_table2(grid.measured, t2);
  for (std::size_t g = 0; g < tables.size(); ++g) {
    const int m = *std::next(configs.begin(), static_cast<std::ptrdiff_t>(g));
    std::vector<BeyondRow> rows;
    for (const int s : {2, 3}) {
      BeyondRow r;
      r.method = "strategy " + std::to_string(s);
      r.ok = true;
      r.cor_rms_t_m = paper.at(m, s).figures.cor_rms_t_m;
      r.n_flagged = paper.at(m, s).figures.n_flagged;
      rows.push_back(r);
    }
    tables[g].rows.insert(tables[g].rows.begin(), rows.begin(), rows.end());
  }
  append(out, std::move(tables));
  beyond_step(on_step);
}

}  // namespace

simulation::TestbedErrorModel lost_motion_errors(simulation::TestbedErrorModel base, bool mixed) {
  constexpr double kArcmin = M_PI / (180.0 * 60.0);
  base.robot.lost_motion_rad = {0.8 * kArcmin, 0.2 * kArcmin, 0.15 * kArcmin,
                                0.7 * kArcmin, 0.6 * kArcmin, 0.4 * kArcmin};
  if (!mixed) {
    base.robot.transmission_amplitude_rad.clear();
    base.robot.transmission_period_rad.clear();
    return base;
  }
  base.robot.compliance = true;
  base.robot.link_mass_kg = {3.7, 8.393, 2.275, 1.219, 1.219, 0.1879};  // UR5 datasheet
  base.robot.joint_stiffness_nm_per_rad = {1e5, 1e5, 1e5, 3e4, 3e4, 3e4};
  base.robot.payload_kg = 0.2;
  base.robot.link_growth = 3.0 * 2.3e-5;
  return base;
}

int beyond_steps(const BeyondOptions& options) {
  return (options.ur5 ? 3 + (options.lost_motion ? 1 : 0) : 0) + (options.lwr4 ? 1 : 0);
}

std::vector<BeyondTable> run_beyond_paper(const BeyondOptions& options,
                                          const std::function<void()>& on_step) {
  std::vector<BeyondTable> out;
  if (options.ur5) beyond_ur5(options, on_step, out);
  if (options.lwr4) beyond_lwr4(options, on_step, out);
  return out;
}

}  // namespace vrreg::experiments
