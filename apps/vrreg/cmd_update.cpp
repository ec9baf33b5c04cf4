// SPDX-License-Identifier: Apache-2.0
// vrreg update: a new version of a model from a few points read today, after `vrreg check` found
// the sensor moved (bump) or the robot drifted (pipeline/update.hpp); the new model names the
// model it came from, the points and the time.
#include <cstdio>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "measurement_input.hpp"
#include "time_option.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/monitor_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::cli {
namespace {

struct UpdateArgs {
  std::string model;
  std::string points;
  std::string change;
  std::string output;
  std::string time;
  std::string history;
  bool even_if_unchanged = false;
  bool json = false;
};

void run_update(const UpdateArgs& args) {
  const RegistrationModel model = io::read_model_json(args.model);
  const MeasurementSet today = read_measurements(args.points);
  UpdateOptions options;
  options.change = args.change == "bump" ? CellChange::kBump : CellChange::kDrift;
  options.parent = args.model;
  options.time = args.time.empty() ? io::utc_now() : args.time;
  options.even_if_unchanged = args.even_if_unchanged;
  if (!args.history.empty()) {
    const std::optional<io::CheckHistoryRow> last =
        io::last_check(io::read_check_history(args.history), monitor_baseline_id(model));
    if (last) options.last_verdict = io::parse_verdict(last->verdict);
  }
  UpdateResult r;
  naming_file(args.model, [&] { r = update_model(model, today, options); });
  io::write_model_json(args.output, r.model);
  if (args.json) {
    nlohmann::json j = io::update_json(r);
    j["model"] = args.model;
    j["points_file"] = args.points;
    j["output"] = args.output;
    print_json(j);
    return;
  }
  std::printf("updated %s (%s) from %zu points of %s: %d monitor, %d fiducial\n",
              args.model.c_str(), args.change.c_str(), r.points.size(), args.points.c_str(),
              r.n_monitors, r.n_fiducials);
  std::printf("  fit RMS residual              %s mm\n", format_mm(r.fit_rms_m).c_str());
  if (r.today_check) {
    std::printf("  today's monitors checked      %s\n",
                to_string(r.today_check->statistics.verdict));
  }
  if (options.change == CellChange::kBump) {
    const Eigen::AngleAxisd turn(r.T_registered_sensor.rotation);
    std::printf("  sensor moved                  %s mrad, %s mm (the correction field is kept)\n",
                format_fixed(1e3 * turn.angle(), 4).c_str(),
                format_mm(r.T_registered_sensor.translation_m.norm()).c_str());
  } else {
    std::printf(
        "  drift at the fiducials        affine in the robot position; fiducials "
        "registered and the corrector (%s) fitted again\n",
        to_string(r.model.interpolation.method));
  }
  std::printf("  version                       %zu updates since registration (%s)\n",
              r.model.lineage.size(), options.time.c_str());
  std::printf("  model written to              %s\n", args.output.c_str());
}

void add_update_command(CLI::App& app) {
  auto args = std::make_shared<UpdateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "update",
      "write a new version of a model from a few points read today: after a bump, the sensor's "
      "move from the monitor points (and any fiducials), the correction field kept; after a "
      "drift, a smooth change fitted to fiducials read again, then registered again; refused "
      "when today's monitor readings show no change (--even-if-unchanged)");
  add_input_option(*cmd, "--model", args->model, "model JSON (with monitor points)")->required();
  add_input_option(*cmd, "--points", args->points,
                   "measurement CSV read today: monitor rows and/or fiducial rows the model knows")
      ->required();
  not_a_file(*cmd, cmd->add_option("--change", args->change, "what changed, as `vrreg check` said")
                       ->required()
                       ->check(CLI::IsMember({"bump", "drift"})));
  add_output_option(*cmd, "-o,--output", args->output, "write the new model JSON here")->required();
  add_time_option(*cmd, args->time);
  add_input_option(*cmd, "--history", args->history,
                   "the cell's check history (vrreg check --history): when today's points have no "
                   "monitor rows to check again, its last check of this model must have found a "
                   "change");
  cmd->add_flag("--even-if-unchanged", args->even_if_unchanged,
                "update even when today's monitor rows, checked again, or the history's last "
                "check of this model found no change (the update would fit noise)");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the summary");
  cmd->callback([args] { run_update(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(28, add_update_command);

}  // namespace vrreg::cli
