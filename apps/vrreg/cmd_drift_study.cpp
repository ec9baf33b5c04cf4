// SPDX-License-Identifier: Apache-2.0
// vrreg drift-study: how well `check` finds a bump of the tracker and a warm-up drift of the robot
// with a few monitor points, how often it alarms on an unchanged cell, and RMS_T after `update`,
// on simulated UR5 A1 cells (docs/monitoring.md).
#include <cstdio>
#include <memory>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/experiments/drift_study.hpp"

namespace vrreg::cli {
namespace {

struct DriftStudyArgs {
  std::uint64_t seed = 1;
  experiments::DriftStudyOptions options;
  double bump_mm = 0.1;
  double drift_mm = 0.2;
};

void add_drift_study_command(CLI::App& app) {
  auto args = std::make_shared<DriftStudyArgs>();
  experiments::DriftStudyOptions& o = args->options;
  CLI::App* cmd = app.add_subcommand(
      "drift-study",
      "measure vrreg check and update on simulated UR5 A1 cells: unchanged, a bump of the "
      "tracker, a warm-up drift of the robot; false alarms, detection, RMS_T after the update");
  add_seed_option(*cmd, "--seed", args->seed, "first seed (cells: seeds N..N+K-1)")
      ->capture_default_str();
  cmd->add_option("--seeds", o.seeds, "number of cells K (all cores)")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--monitors", o.monitors, "monitor points per cell")
      ->capture_default_str()
      ->check(CLI::Range(3, 100));
  cmd->add_option("--visits", o.visits, "visits of each monitor point per reading")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  cmd->add_option("--bump-mm", args->bump_mm, "the bump's RMS displacement over the targets")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--drift-mm", args->drift_mm, "the warm-up's RMS displacement of the TCP")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--points", o.update_points, "points read for an update, monitors included")
      ->capture_default_str()
      ->check(CLI::Range(4, 1000));
  cmd->add_option("--false-alarm-rate", o.false_alarm_rate,
                  "chance that check calls an unchanged cell changed")
      ->capture_default_str()
      ->check(CLI::Range(1e-9, 0.49));
  cmd->callback([args] {
    experiments::DriftStudyOptions options = args->options;
    options.first_seed = args->seed;
    options.bump_rms_m = units::mm_to_m(args->bump_mm);
    options.drift_rms_m = units::mm_to_m(args->drift_mm);
    std::fputs(experiments::drift_study_text(experiments::drift_study(options)).c_str(), stdout);
  });
}

}  // namespace

VRREG_REGISTER_COMMAND(96, add_drift_study_command);

}  // namespace vrreg::cli
