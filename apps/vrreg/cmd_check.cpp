// SPDX-License-Identifier: Apache-2.0
// vrreg check: does a registration still hold? Today's readings of the model's monitor points
// against their readings at registration (pipeline/check.hpp), told with the checks before it
// when a history is given; the exit status says what changed.
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "measurement_input.hpp"
#include "time_option.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/monitor_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::cli {
namespace {

struct CheckArgs {
  std::string model;
  std::string monitor;
  double false_alarm_rate = CheckOptions{}.false_alarm_rate;
  std::optional<double> visit_sd_mm;
  int remeasure = CheckOptions{}.remeasure;
  std::string history;
  std::string time;
  bool json = false;
};

int exit_status(MonitorVerdict verdict) {
  switch (verdict) {
    case MonitorVerdict::kValid:
      return 0;
    case MonitorVerdict::kRigidChange:
      return 10;
    case MonitorVerdict::kSmoothChange:
      return 11;
    case MonitorVerdict::kOutlier:
      return 12;
    case MonitorVerdict::kNoisier:
      return 13;
  }
  return 1;
}

void print_text(const CheckArgs& args, const CheckResult& r) {
  const MonitorCheck& s = r.statistics;
  std::printf("checked %zu of the model's %d monitor points from %s against model %s\n",
              r.points.size(), r.model_monitors, args.monitor.c_str(), args.model.c_str());
  std::printf("  verdict                       %s\n", to_string(s.verdict));
  std::printf("  why                           %s\n", s.message.c_str());
  std::printf("  visit sd                      %s mm per axis at registration, %s mm today (%s)\n",
              format_mm(r.visit_sd_m).c_str(), format_mm(r.today_visit_sd_m).c_str(),
              r.variance_dof > 0.0
                  ? fmt::format("from the visits' scatter, {:.0f} dof", r.variance_dof).c_str()
                  : "given");
  if (r.noise.tested) {
    std::printf(
        "  today's noise                 %.2f times the registration's variance (p = "
        "%.2g)%s\n",
        r.noise.ratio, r.noise.p_value, r.noise.noisier ? ": noisier today" : "");
  }
  std::printf("  change at the monitor points  %s mm RMS\n", format_mm(s.change_rms_m).c_str());
  std::printf("  %-12s %7s %7s %10s %10s\n", "point", "then", "today", "moved mm", "sd mm");
  for (const MonitorPointCheck& p : r.points) {
    std::printf("  %-12s %7d %7d %10s %10s\n",
                (p.config ? p.point + "@" + std::to_string(*p.config) : p.point).c_str(),
                p.baseline_visits, p.today_visits, format_mm(p.difference_m.norm()).c_str(),
                format_mm(p.difference_sd_m).c_str());
  }
  for (const std::string& blind : s.blind_spots)
    std::printf("  cannot tell                   %s\n", blind.c_str());
  if (!args.history.empty() && s.verdict != MonitorVerdict::kValid &&
      s.verdict != MonitorVerdict::kNoisier && s.verdict != MonitorVerdict::kOutlier) {
    std::printf("  how it came                   %s (%d earlier checks of this model in %s)\n",
                to_string(r.onset.onset), r.onset.earlier_checks, args.history.c_str());
  }
  if (s.verdict == MonitorVerdict::kRigidChange && s.rigid) {
    if (s.rigid->rotation_rank == 3) {
      std::printf("  sensor moved                  %s mrad, %s mm RMS at the monitor points\n",
                  format_fixed(1e3 * s.rigid->rotation_rad.norm(), 4).c_str(),
                  format_mm(s.rigid->displacement_rms_m).c_str());
    } else {
      std::printf(
          "  moved at the monitor points   %s mm (their centroid; a turn of the sensor "
          "is not fully seen)\n",
          format_mm3(s.rigid->translation_at_centroid_m).c_str());
    }
  }
  if (s.verdict == MonitorVerdict::kRigidChange && r.remeasure.empty()) {
    std::printf(
        "  next                          vrreg update --model %s --points TODAY.csv "
        "--change bump -o NEW.json (monitors and up to 10 fiducials)\n",
        args.model.c_str());
  }
  if (!r.remeasure.empty()) {
    const bool bump = s.verdict == MonitorVerdict::kRigidChange;
    std::printf("  read %s %zu fiducials:", bump ? "with the monitors" : "again          ",
                r.remeasure.size());
    for (const std::string& f : r.remeasure) std::printf(" %s", f.c_str());
    std::printf(
        "\n  next                          vrreg update --model %s --points TODAY.csv "
        "--change %s -o NEW.json%s\n",
        args.model.c_str(), bump ? "bump" : "drift",
        bump ? " (a bump update needs 3 or more points)" : "");
  }
  if (s.verdict == MonitorVerdict::kNoisier) {
    std::printf(
        "  next                          check again (more visits, a quieter cell); no "
        "update: nothing was found to update\n");
  }
  if (!args.history.empty())
    std::printf("  history                       %s\n", args.history.c_str());
}

void run_check(const CheckArgs& args) {
  const RegistrationModel model = io::read_model_json(args.model);
  const MeasurementSet today = read_measurements(args.monitor);
  CheckOptions options;
  options.false_alarm_rate = args.false_alarm_rate;
  if (args.visit_sd_mm) options.visit_sd_m = units::mm_to_m(*args.visit_sd_mm);
  options.remeasure = args.remeasure;
  const std::string time = args.time.empty() ? io::utc_now() : args.time;
  options.time_s = io::parse_iso8601_s(time);
  if (!args.history.empty() && std::filesystem::exists(args.history)) {
    options.earlier =
        io::earlier_checks(io::read_check_history(args.history), monitor_baseline_id(model), time);
  }
  CheckResult r;
  naming_file(args.model, [&] { r = check_cell(model, today, options); });
  if (!args.history.empty()) io::append_check_history(args.history, time, args.monitor, r);
  if (args.json) {
    nlohmann::json j = io::check_json(r);
    j["model"] = args.model;
    j["monitor"] = args.monitor;
    j["time"] = time;
    print_json(j);
  } else {
    print_text(args, r);
  }
  const int status = exit_status(r.statistics.verdict);
  if (status != 0) throw CellChanged(status, to_string(r.statistics.verdict));
}

void add_check_command(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "check",
      "does the registration still hold? compare today's readings of the model's monitor points "
      "with their readings at registration; exit 0 valid, 10 the sensor moved (bump), 11 the "
      "robot drifted, 12 one monitor point moved, 13 noisier today (nothing found, the readings "
      "scatter more than at registration)");
  add_input_option(*cmd, "--model", args->model, "model JSON with monitor points")->required();
  add_input_option(*cmd, "--monitor", args->monitor,
                   "measurement CSV; its monitor rows (role monitor, any visits) are used")
      ->required();
  cmd->add_option("--false-alarm-rate", args->false_alarm_rate,
                  "chance that an unchanged cell is called changed (or noisier)")
      ->capture_default_str()
      ->check(CLI::Range(1e-9, 0.49));
  cmd->add_option("--visit-sd-mm", args->visit_sd_mm,
                  "sd of one visit's mean reading per axis, when known (default: estimated from "
                  "the visits' scatter, at registration and today apart)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--remeasure", args->remeasure,
                  "after a drift: how many fiducials to name for reading again")
      ->capture_default_str()
      ->check(CLI::Range(4, 100000));
  add_output_option(*cmd, "--history", args->history,
                    "append this check (time, verdict, each point's move) to the cell's CSV "
                    "history; its earlier checks of this model tell a change that came at once "
                    "(a bump) from one that grew (a drift)");
  add_time_option(*cmd, args->time);
  cmd->add_flag("--json", args->json, "print one JSON object instead of the table");
  cmd->callback([args] { run_check(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(27, add_check_command);

}  // namespace vrreg::cli
