// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/drift_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "seed_cells.hpp"
#include "text_table.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/planning/spread_points.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/cell_events.hpp"
#include "vrreg/simulation/read_locations.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::experiments {
namespace {

constexpr DriftScenario kDriftScenarios[] = {DriftScenario::kUnchanged, DriftScenario::kBump,
                                             DriftScenario::kDrift};

// Streams apart from the simulation's, one per acquisition, so each scenario's noise is its own.
constexpr std::uint64_t kMonitorStream = 0xd81f7000000000a1ULL;

// The commanded locations of `rows` of the cell (their nominal position and joints).
std::vector<simulation::CommandedLocation> commanded(const MeasurementSet& set,
                                                     const std::vector<std::size_t>& rows,
                                                     Role role) {
  std::vector<simulation::CommandedLocation> out;
  for (const std::size_t i : rows) {
    const Location& l = set.locations[i];
    out.push_back({l.point, role, l.robot_m, l.config,
                   Eigen::Map<const Eigen::VectorXd>(l.q_rad.data(),
                                                     static_cast<Eigen::Index>(l.q_rad.size()))});
  }
  return out;
}

MeasurementSet set_of(std::vector<Location> locations, const std::string& source) {
  MeasurementSet set;
  set.source = source;
  set.has_visit = true;
  set.n_joints = locations.empty() ? 0 : static_cast<int>(locations.front().q_rad.size());
  set.locations = std::move(locations);
  return set;
}

// The cell's target rows with their sensor readings moved (a bump) or read anew (a drift).
MeasurementSet targets_of(const MeasurementSet& cell) {
  MeasurementSet t = cell;
  std::erase_if(t.locations, [](const Location& l) { return l.role != Role::kTarget; });
  return t;
}

double cor_rms_t(const RegistrationModel& model, const MeasurementSet& targets) {
  return evaluate(model, targets).summary.cor_rms_t_m;
}

struct DriftCell {
  MeasurementSet set;  // fiducials, targets, the monitors' registration visits
  std::vector<std::size_t> fiducials, targets;
  std::vector<simulation::CommandedLocation> monitors;
  std::vector<simulation::CommandedLocation> update_fiducials;  // read with the monitors
  std::optional<simulation::SimulatedRobot> robot;
  RigidTransform T_robot_sensor;
  simulation::TrackerModel tracker;
  RegistrationModel model;
  double cor_rms_t_m = 0.0;
};

DriftCell make_cell(std::uint64_t seed, const DriftStudyOptions& options) {
  DriftCell c;
  const simulation::Testbed testbed = simulation::ur5_testbed();
  simulation::SimulationOptions sim;
  sim.seed = seed;
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, simulation::Dataset::kA1, sim);
  c.set = to_measurement_set(data);
  c.fiducials = c.set.select(Role::kFiducial);
  c.targets = c.set.select(Role::kTarget);
  c.robot.emplace(testbed.nominal, data.errors.robot, data.robot);
  c.T_robot_sensor = data.T_robot_sensor;
  c.tracker = data.errors.tracker;
  // Monitor points and the fiducials an update reads: spread over the fiducials.
  const Points3 fiducials_robot = c.set.robot_points(c.fiducials);
  const std::vector<std::size_t> spread = planning::spread_points(
      fiducials_robot, static_cast<std::size_t>(std::max(options.update_points, options.monitors)));
  std::vector<std::size_t> monitor_rows, update_rows;
  for (std::size_t k = 0; k < spread.size(); ++k) {
    (k < static_cast<std::size_t>(options.monitors) ? monitor_rows : update_rows)
        .push_back(c.fiducials[spread[k]]);
  }
  c.monitors = commanded(c.set, monitor_rows, Role::kMonitor);
  for (simulation::CommandedLocation& m : c.monitors) m.point = "monitor-" + m.point;
  c.update_fiducials = commanded(c.set, update_rows, Role::kFiducial);
  Random rng = Random::stream(seed, kMonitorStream);
  for (Location& m : simulation::read_locations(*c.robot, c.T_robot_sensor, c.tracker, c.monitors,
                                                options.visits, rng)) {
    c.set.locations.push_back(std::move(m));
  }
  RegisterOptions reg;
  reg.rigid_body_statistics = false;
  c.model = register_fiducials(c.set, reg).model;
  c.cor_rms_t_m = cor_rms_t(c.model, targets_of(c.set));
  return c;
}

DriftStudyCell run(const DriftCell& c, std::uint64_t seed, DriftScenario scenario,
                   const DriftStudyOptions& options) {
  DriftStudyCell out;
  out.seed = seed;
  out.scenario = scenario;
  out.cor_rms_t_m = c.cor_rms_t_m;
  Random rng = Random::stream(seed, kMonitorStream + 1 + static_cast<std::uint64_t>(scenario));
  simulation::SimulatedRobot robot = *c.robot;
  RigidTransform T_robot_sensor = c.T_robot_sensor;
  MeasurementSet targets = targets_of(c.set);
  if (scenario == DriftScenario::kBump) {
    const RigidTransform T_after_before = simulation::draw_bump(
        targets.sensor_points(targets.select(Role::kTarget)), options.bump_rms_m, rng);
    T_robot_sensor = T_robot_sensor * T_after_before.inverse();
    // The same target readings in the moved frame: what changes is the registration only.
    for (Location& t : targets.locations) t.sensor_m = T_after_before.apply(t.sensor_m);
  } else if (scenario == DriftScenario::kDrift) {
    const std::vector<std::size_t> rows = targets.select(Role::kTarget);
    Eigen::MatrixXd q(c.robot->nominal().n_joints(), static_cast<Eigen::Index>(rows.size()));
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const std::vector<double>& qk = targets.locations[rows[k]].q_rad;
      q.col(static_cast<Eigen::Index>(k)) =
          Eigen::Map<const Eigen::VectorXd>(qk.data(), static_cast<Eigen::Index>(qk.size()));
    }
    robot = simulation::grown(robot,
                              simulation::growth_for_displacement(robot, q, options.drift_rms_m));
    // The targets read again: the robot puts them elsewhere now.
    const std::vector<Location> again = simulation::read_locations(
        robot, T_robot_sensor, c.tracker, commanded(targets, rows, Role::kTarget), 1, rng);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      targets.locations[rows[k]].sensor_m = again[k].sensor_m;
      targets.locations[rows[k]].sensor_sq_dev_m2 = again[k].sensor_sq_dev_m2;
    }
  }
  const MeasurementSet today = set_of(
      simulation::read_locations(robot, T_robot_sensor, c.tracker, c.monitors, options.visits, rng),
      "monitors seed " + std::to_string(seed));
  CheckOptions check;
  check.false_alarm_rate = options.false_alarm_rate;
  check.remeasure = options.update_points - options.monitors;
  const CheckResult verdict = check_cell(c.model, today, check);
  out.verdict = verdict.statistics.verdict;
  out.change_rms_m = verdict.statistics.change_rms_m;
  out.stale_rms_t_m = cor_rms_t(c.model, targets);
  out.updated_rms_t_m = out.stale_rms_t_m;
  if (scenario == DriftScenario::kUnchanged) return out;
  // The update reads the monitors (today's visits) and a few fiducials once each.
  std::vector<Location> points = today.locations;
  for (Location& f :
       simulation::read_locations(robot, T_robot_sensor, c.tracker, c.update_fiducials, 1, rng)) {
    points.push_back(std::move(f));
  }
  UpdateOptions update;
  update.change = scenario == DriftScenario::kBump ? CellChange::kBump : CellChange::kDrift;
  update.even_if_unchanged = true;  // the study measures every update, whatever the check said
  update.parent = "seed " + std::to_string(seed);
  const UpdateResult updated = update_model(
      c.model, set_of(std::move(points), "update seed " + std::to_string(seed)), update);
  out.update_fit_rms_m = updated.fit_rms_m;
  out.updated_rms_t_m = cor_rms_t(updated.model, targets);
  return out;
}

}  // namespace

void DriftStudyOptions::validate() const {
  VRREG_THROW_UNLESS(seeds >= 1, "drift study: need at least 1 seed, got " << seeds);
  check_seed_run(first_seed, static_cast<std::uint64_t>(seeds), "drift study");
  VRREG_THROW_UNLESS(monitors >= 3, "drift study: need 3 or more monitor points");
  VRREG_THROW_UNLESS(visits >= 1, "drift study: need 1 or more visits");
  VRREG_THROW_UNLESS(update_points >= monitors + 4 - std::min(monitors, 3) && update_points >= 4,
                     "drift study: an update needs 4 or more points");
  VRREG_THROW_UNLESS(std::isfinite(bump_rms_m) && bump_rms_m >= 0.0 && std::isfinite(drift_rms_m) &&
                         drift_rms_m >= 0.0,
                     "drift study: sizes must be >= 0");
  MonitorCheckOptions{false_alarm_rate, 0.0}.validate();
}

const char* to_string(DriftScenario scenario) {
  switch (scenario) {
    case DriftScenario::kUnchanged:
      return "unchanged";
    case DriftScenario::kBump:
      return "bump";
    case DriftScenario::kDrift:
      return "warm-up drift";
  }
  return "?";
}

DriftStudy drift_study(const DriftStudyOptions& options) {
  options.validate();
  DriftStudy study;
  study.options = options;
  study.cells = detail::seed_cells<DriftStudyCell>(
      options.first_seed, static_cast<std::size_t>(options.seeds),
      std::span<const DriftScenario>(kDriftScenarios),
      [&](std::uint64_t seed) { return make_cell(seed, options); },
      [&](const DriftCell& cell, std::uint64_t seed, DriftScenario scenario) {
        return run(cell, seed, scenario, options);
      });
  return study;
}

std::string drift_study_text(const DriftStudy& study) {
  const DriftStudyOptions& o = study.options;
  std::string out = fmt::format(
      "monitor check on simulated UR5 A1 cells, seeds {}..{}: {} monitor points x {} visits, "
      "false-alarm rate {}; bump {:.3f} mm RMS over the targets, warm-up drift {:.3f} mm RMS; "
      "updates from {} points (monitors included)\n",
      o.first_seed, o.first_seed + static_cast<std::uint64_t>(o.seeds) - 1, o.monitors, o.visits,
      o.false_alarm_rate, o.bump_rms_m * 1e3, o.drift_rms_m * 1e3, o.update_points);
  text::TextTable table;
  table.add({"scenario", "cells", "valid", "rigid", "outlier", "smooth", "changed", "corRMS_T mm",
             "stale mm", "updated mm", "worst updated/before"});
  for (const DriftScenario scenario : kDriftScenarios) {
    int n = 0;
    int count[5] = {0, 0, 0, 0, 0};  // per MonitorVerdict
    double before = 0.0, stale = 0.0, updated = 0.0, worst = 0.0;
    for (const DriftStudyCell& c : study.cells) {
      if (c.scenario != scenario) continue;
      ++n;
      ++count[static_cast<int>(c.verdict)];
      before += c.cor_rms_t_m;
      stale += c.stale_rms_t_m;
      updated += c.updated_rms_t_m;
      worst = std::max(worst, c.updated_rms_t_m / c.cor_rms_t_m);
    }
    const auto rate = [n](int k) {
      return fmt::format("{} ({:.1f}%)", k, 100.0 * k / std::max(n, 1));
    };
    const bool updates = scenario != DriftScenario::kUnchanged;
    table.add({to_string(scenario), std::to_string(n), rate(count[0]), rate(count[1]),
               rate(count[2]), rate(count[3]), rate(n - count[0]),
               text::decimal_text(before / n * 1e3, 4), text::decimal_text(stale / n * 1e3, 4),
               updates ? text::decimal_text(updated / n * 1e3, 4) : "-",
               updates ? text::decimal_text(worst, 3) : "-"});
  }
  out += table.str();
  return out;
}

}  // namespace vrreg::experiments
