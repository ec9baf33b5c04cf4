// SPDX-License-Identifier: Apache-2.0
// vrreg simulate: the paper's datasets acquired on a simulated test bed (UR5: A1, A2, B; KUKA
// LWR 4+: grid), or a plan of `vrreg plan` measured on it (--plan), written as a measurement CSV.
// Same seed, same bytes.
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/plan_csv.hpp"
#include "vrreg/robot_io/error_model_file.hpp"
#include "vrreg/robot_io/simulation_csv.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"

namespace vrreg::cli {
namespace {

struct SimulateArgs {
  std::string testbed;
  std::string dataset;
  std::uint64_t seed = 1;
  std::string errors;
  std::string output;
  std::string write_errors;
  std::string plan;
  std::vector<double> marker_flange_mm;
  bool unknown_marker = false;
  int monitor_visits = 12;
  double at_h = 0.0;
  double bump_mm = 0.0;
  double bump_at_h = 0.0;
  double warmup_growth = 0.0;
  double rigid_body_mm = 0.0;
  std::vector<double> body_mount_deg;
  double warmup_tau_h = 0.5;
  double daily_growth = 0.0;
  std::string only;
};

// The plan's rows as the robot program is told them; errors name the plan file.
simulation::SimulatedDataset simulate_plan_file(const simulation::Testbed& testbed,
                                                const std::string& path,
                                                const simulation::SimulationOptions& options,
                                                const std::string& only) {
  const io::PlanFile plan = io::read_plan_csv(path);
  if (plan.n_joints == 0) {
    throw io::FileError(path, 0,
                        "the plan has no joint columns (q1_rad..qN_rad): the simulated robot is "
                        "sent joints; make the plan with 'vrreg plan --robot " +
                            testbed.name + "'");
  }
  std::vector<simulation::CommandedLocation> commanded;
  for (const io::PlanRow& row : plan.rows) {
    if (!only.empty() && to_string(row.role) != only) continue;
    simulation::CommandedLocation c;
    c.point = row.point;
    c.role = row.role;
    c.robot_m = row.robot_m;
    c.config = row.config;
    c.q_rad = Eigen::Map<const Eigen::VectorXd>(row.q_rad.data(),
                                                static_cast<Eigen::Index>(row.q_rad.size()));
    if (row.via) {
      c.via_q_rad = Eigen::Map<const Eigen::VectorXd>(
          row.via->q_rad.data(), static_cast<Eigen::Index>(row.via->q_rad.size()));
    }
    commanded.push_back(std::move(c));
  }
  if (commanded.empty()) throw io::FileError(path, 0, "the plan has no " + only + " rows");
  try {
    return simulation::simulate_plan(testbed, commanded, options);
  } catch (const InputError& e) {
    throw io::FileError(path, 0, e.what());
  }
}

void run_simulate(const SimulateArgs& args) {
  const simulation::Testbed testbed = simulation::testbed_by_name(args.testbed);
  simulation::SimulationOptions options;
  options.seed = args.seed;
  if (!args.marker_flange_mm.empty()) {
    for (const double v : args.marker_flange_mm) {
      VRREG_THROW_UNLESS(std::isfinite(v), "--marker-flange-mm: values must be finite");
    }
    options.marker_flange_m = 1e-3 * Eigen::Vector3d(
        args.marker_flange_mm[0], args.marker_flange_mm[1], args.marker_flange_mm[2]);
  } else if (args.unknown_marker) {
    options.marker_flange_m = simulation::kRealisticMarkerFlangeM;
  }
  if (!args.errors.empty()) options.errors = io::read_error_model_file(args.errors, testbed);
  if (args.rigid_body_mm > 0.0) {
    options.errors = options.errors.value_or(testbed.default_errors);
    options.errors->tracker.rigid_body_radius_m = 1e-3 * args.rigid_body_mm;
  }
  if (!args.body_mount_deg.empty()) {
    VRREG_THROW_UNLESS(args.rigid_body_mm > 0.0, "--body-mount-deg needs --rigid-body-mm");
    for (const double v : args.body_mount_deg) {
      VRREG_THROW_UNLESS(std::isfinite(v), "--body-mount-deg: values must be finite");
    }
    options.body_mount_rotation_rad =
        units::kRadiansPerDegree *
        Eigen::Vector3d(args.body_mount_deg[0], args.body_mount_deg[1], args.body_mount_deg[2]);
  }
  // Time: a check hours after registration sees the warm-up and any bump since.
  constexpr double kSecondsPerHour = 3600.0;
  options.monitor_visits = args.monitor_visits;
  options.time_s = args.at_h * kSecondsPerHour;
  options.events.thermal.warmup_growth = args.warmup_growth;
  options.events.thermal.warmup_time_constant_s = args.warmup_tau_h * kSecondsPerHour;
  options.events.thermal.daily_growth = args.daily_growth;
  if (args.bump_mm > 0.0) {
    options.events.bump_rms_m = 1e-3 * args.bump_mm;
    options.events.bump_time_s = args.bump_at_h * kSecondsPerHour;
  }
  VRREG_THROW_UNLESS(args.only.empty() || !args.plan.empty(), "--only goes with --plan");
  // Both outputs are made before either is written, then written together or not at all.
  std::vector<io::OutputFile> outputs;
  if (!args.write_errors.empty()) {
    outputs.push_back(
        {args.write_errors,
         io::format_error_model(options.errors.value_or(testbed.default_errors), testbed.name)});
  }
  const auto say_errors_written = [&] {
    if (args.write_errors.empty()) return;
    std::printf("error model of test bed %s written to %s\n", testbed.name.c_str(),
                args.write_errors.c_str());
  };
  if (args.output.empty()) {
    VRREG_THROW_UNLESS(!args.write_errors.empty(),
                       "simulate: nothing to do: give -o FILE.csv (and a DATASET)");
    io::write_files_atomically(outputs);
    say_errors_written();
    return;
  }
  VRREG_THROW_UNLESS(args.plan.empty() || args.dataset.empty(),
                     "simulate: give a DATASET or --plan FILE, not both");
  VRREG_THROW_UNLESS(!args.dataset.empty() || !args.plan.empty(),
                     "simulate: give a DATASET (ur5: A1, A2 or B; lwr4: grid) or --plan FILE");
  simulation::SimulatedDataset data;
  if (!args.plan.empty()) {
    data = simulate_plan_file(testbed, args.plan, options, args.only);
  } else {
    const simulation::Dataset dataset = simulation::parse_dataset(args.dataset);
    simulation::check_dataset(testbed.kind, dataset);
    data = simulation::simulate_dataset(testbed, dataset, options);
  }
  outputs.push_back(
      {args.output, io::format_measurement_csv(io::simulated_readings(data),
                                               io::simulated_dataset_comments(data))});
  io::write_files_atomically(outputs);
  say_errors_written();
  std::size_t targets = 0, monitors = 0;
  for (const auto& location : data.locations) {
    targets += location.role == Role::kTarget ? 1 : 0;
    monitors += location.role == Role::kMonitor ? 1 : 0;
  }
  const std::string what =
      args.plan.empty() ? simulation::to_string(data.dataset) : "plan " + args.plan;
  std::printf(
      "simulated %s %s with seed %llu%s\n", testbed.name.c_str(), what.c_str(),
      static_cast<unsigned long long>(args.seed),
      args.errors.empty() ? " (default errors)" : (" (errors from " + args.errors + ")").c_str());
  std::printf("  %zu locations (%zu fiducials, %zu targets%s), %zu visits, %zu readings\n",
              data.locations.size(), data.locations.size() - targets - monitors, targets,
              monitors > 0 ? (", " + std::to_string(monitors) + " monitor points").c_str() : "",
              data.visits.size(), data.readings.size());
  if (data.marker_flange_m) {
    std::printf("  true marker in the flange frame %s mm (robot_*_mm: the controller's TCP)\n",
                format_mm3(*data.marker_flange_m, 3).c_str());
  }
  if (options.time_s != 0.0) {
    std::printf("  at %s h: links grown by %s (warm-up), tracker %s\n",
                format_fixed(args.at_h, 2).c_str(),
                format_fixed(options.events.thermal.growth_at(options.time_s), 7).c_str(),
                options.time_s >= options.events.bump_time_s
                    ? ("bumped " + format_fixed(args.bump_mm, 3) + " mm RMS").c_str()
                    : "as at time 0");
  }
  std::printf("  written to %s\n", args.output.c_str());
}

void add_simulate_command(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "acquire one of the paper's datasets on a simulated test bed (ur5: A1, A2, B; "
      "lwr4: grid), or measure a plan (--plan), and write it as a measurement CSV");
  not_a_file(*cmd, cmd->add_option("TESTBED", args->testbed, "ur5 or lwr4")->required());
  not_a_file(*cmd, cmd->add_option("DATASET", args->dataset,
                                   "ur5: A1, A2 or B; lwr4: grid (or give --plan)"));
  add_input_option(*cmd, "--plan", args->plan,
                   "measure this plan of 'vrreg plan --robot TESTBED' instead of a dataset: the "
                   "robot takes its joints, the tracker reads each location K times; then "
                   "'vrreg register' and 'vrreg evaluate --cube-mm SPACING' predict its accuracy");
  cmd->add_option("--monitor-visits", args->monitor_visits,
                  "with --plan: visits of each monitor point (role monitor), in rounds at the end")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  not_a_file(*cmd, cmd->add_option("--only", args->only,
                                   "with --plan: measure only the rows of this role (monitor: a "
                                   "check)")
                       ->check(CLI::IsMember({"fiducial", "target", "monitor"})));
  cmd->add_option("--at-h", args->at_h,
                  "acquire this many hours after time 0 (registration): the warm-up and a bump "
                  "since then apply, the noise is drawn afresh")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e5));
  cmd->add_option("--bump-mm", args->bump_mm,
                  "the tracker is bumped at --bump-at-h by this RMS displacement over the work "
                  "volume (its direction drawn from the seed)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--bump-at-h", args->bump_at_h, "when the bump happens, hours")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e5));
  cmd->add_option("--warmup-growth", args->warmup_growth,
                  "relative growth of every link at full warm-up (alpha dT, e.g. 2e-4)")
      ->check(CLI::Range(-0.005, 0.005));
  cmd->add_option("--warmup-tau-h", args->warmup_tau_h, "warm-up time constant, hours")
      ->capture_default_str()
      ->check(CLI::Range(1e-3, 1e3));
  cmd->add_option("--daily-growth", args->daily_growth,
                  "amplitude of the day's relative link growth (24 h period)")
      ->check(CLI::Range(-0.005, 0.005));
  cmd->add_option("--rigid-body-mm", args->rigid_body_mm,
                  "track a rigid body of 4 spheres on a circle of this radius, mm, about the "
                  "marker: adds the measured (sensor_q*) and commanded (robot_q*) orientations; "
                  "positions stay as without it")
      ->check(CLI::Range(0.0, 1000.0));
  cmd->add_option("--body-mount-deg", args->body_mount_deg,
                  "RX RY RZ: the rigid body mounted turned by this rotation vector (deg) in the "
                  "tool frame it is commanded in (a mounting error); positions stay as without it")
      ->expected(3);
  add_seed_option(*cmd, "--seed", args->seed,
                  "draws the robot's errors and the noise; the same seed gives the same file")
      ->capture_default_str();
  add_input_option(*cmd, "--errors", args->errors,
                   "error-model file (JSON or YAML) over the test bed's defaults; see "
                   "--write-errors");
  CLI::Option* marker =
      cmd->add_option("--marker-flange-mm", args->marker_flange_mm,
                      "X Y Z: where the tracked marker really sits in the flange frame, mm (a cell "
                      "whose offset is unknown: robot_*_mm stay the controller's TCP); default the "
                      "test bed's tool, as in the paper")
          ->expected(3);
  cmd->add_flag("--unknown-marker", args->unknown_marker,
                "the marker at a realistic unknown offset, (35, -25, 85) mm in the flange frame")
      ->excludes(marker);
  add_output_option(*cmd, "-o,--output", args->output, "measurement CSV to write");
  add_output_option(*cmd, "--write-errors", args->write_errors,
                    "write the error model in use (defaults, or --errors) to this JSON file");
  cmd->callback([args] { run_simulate(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(40, add_simulate_command);

}  // namespace vrreg::cli
