// SPDX-License-Identifier: Apache-2.0
// vrreg robust-study: how often `register --robust` finds a displaced or swapped fiducial, and how
// often it rejects a good one, on simulated UR5 A1 cells (docs/outliers.md).
#include <cstdio>
#include <memory>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/experiments/robust_study.hpp"

namespace vrreg::cli {
namespace {

struct RobustStudyArgs {
  std::uint64_t seed = 1;
  int seeds = 30;
  std::optional<double> sigma_rep_mm;
  double false_alarm_rate = OutlierOptions{}.false_alarm_rate;
};

void run_robust_study(const RobustStudyArgs& args) {
  experiments::RobustStudyOptions options;
  options.first_seed = args.seed;
  options.seeds = args.seeds;
  if (args.sigma_rep_mm) options.sigma_rep_m = units::mm_to_m(*args.sigma_rep_mm);
  options.outliers.false_alarm_rate = args.false_alarm_rate;
  std::fputs(experiments::robust_study_text(experiments::robust_study(options)).c_str(), stdout);
}

void add_robust_study_command(CLI::App& app) {
  auto args = std::make_shared<RobustStudyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "robust-study",
      "measure register --robust on simulated UR5 A1 cells: one fiducial displaced by 1 or 2 mm, "
      "two swapped, none; how often it is found, how often a good one is rejected, RMS_T");
  add_seed_option(*cmd, "--seed", args->seed, "first seed (cells: seeds N..N+K-1)")
      ->capture_default_str();
  cmd->add_option("--seeds", args->seeds, "number of cells K (all cores)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--sigma-rep-mm", args->sigma_rep_mm,
                  "robot repeatability given to register, for sigma_noise (UR5 0.1)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--false-alarm-rate", args->false_alarm_rate,
                  "chance that a clean cell loses any fiducial")
      ->capture_default_str()
      ->check(CLI::Range(1e-12, 0.5));
  cmd->callback([args] { run_robust_study(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(95, add_robust_study_command);

}  // namespace vrreg::cli
