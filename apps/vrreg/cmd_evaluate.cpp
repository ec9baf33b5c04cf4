// SPDX-License-Identifier: Apache-2.0
// vrreg evaluate: the true accuracy of a registration on independent targets: TRE and RMS_T
// uncorrected and RRBC-corrected (Eq. 3, 4, 7, 8), gamma, N_bad and Delta TRE (section 5.1),
// following the model's Procedure 2 strategy (section 4.4, strategy_cli.hpp).
#include <algorithm>
#include <cstdio>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "field_model_cli.hpp"
#include "measurement_input.hpp"
#include "robot_cli.hpp"
#include "strategy_cli.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/result_json.hpp"
#include "vrreg/io/results_csv.hpp"
#include "vrreg/metrics/multidirectional.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::cli {
namespace {

struct EvaluateArgs {
  std::string model;
  std::string targets;
  std::optional<int> config;
  InterpolationFlags interpolation;
  StrategyFlags strategy;
  std::string per_target;
  std::string robot;
  RobotLinkFlags links;
  bool json = false;
};

void print_multidirectional(const MultidirectionalAccuracy& m) {
  std::printf("  multi-directional (ISO 9283)  %d target point%s visited from %zu directions\n",
              m.n_points, m.n_points == 1 ? "" : "s", m.directions.size());
  for (const DirectionAccuracy& d : m.directions) {
    std::printf("    RMS_T approach %-13s %8s mm  %8s mm  (%d targets)\n",
                approach_text(d.approach_sign).c_str(), format_mm(d.unc_rms_t_m).c_str(),
                format_mm(d.cor_rms_t_m).c_str(), d.n_targets);
  }
  std::printf("    spread between directions   %8s mm  %8s mm  (max over points)\n",
              format_mm(m.unc_max_spread_m).c_str(), format_mm(m.cor_max_spread_m).c_str());
  std::printf("                                %8s mm  %8s mm  (mean)\n",
              format_mm(m.unc_mean_spread_m).c_str(), format_mm(m.cor_mean_spread_m).c_str());
}

void run_evaluate_unchecked(const EvaluateArgs& args, const RegistrationModel& model) {
  EvaluateOptions options;
  options.config = args.config;
  options.interpolation = args.interpolation.choice();
  options.refit = args.interpolation.refit;
  options.extrapolate = args.interpolation.extrapolate;
  options.exact = args.interpolation.exact;
  apply_evaluate_flags(args.strategy, options);
  if (!args.robot.empty()) {
    const kinematics::SerialChain* remembered = model.robot ? &*model.robot : nullptr;
    options.robot = robot_from_args(args.robot, {}, args.links.links(remembered));
  }
  const MeasurementSet targets = read_measurements(args.targets);
  const EvaluateResult r = evaluate(model, targets, options);
  const ImprovementSummary& s = r.summary;
  const TargetCorrection& c = r.correction;
  const std::optional<int>& config = r.config;
  const std::vector<std::string>& bad = r.bad_targets;
  const std::optional<planning::Strategy2Summary>& relabelled = r.relabelled;

  if (!args.per_target.empty()) io::write_per_target_csv(args.per_target, r);

  if (args.json) {
    nlohmann::json j = io::evaluate_json(r, model);
    j["model"] = args.model;
    j["targets"] = args.targets;
    print_json(j);
    return;
  }
  std::printf("evaluated %d targets from %s with model %s%s\n", r.n_targets(), args.targets.c_str(),
              args.model.c_str(),
              config ? (" (config " + std::to_string(*config) + ")").c_str() : "");
  print_strategy(model, relabelled);
  if (r.cross_validation) print_cross_validation(*r.cross_validation);
  std::printf("  interpolation                 %s: %s\n", to_string(c.method_used),
              c.layout.c_str());
  if (c.guard && !c.guard->applied) print_guard(*c.guard);
  if (c.n_flagged > 0) {
    std::printf(
        "  not correctable               %d target%s (%s; left uncorrected, RMS_T %s mm as "
        "registered; not in the figures below)\n",
        c.n_flagged, c.n_flagged == 1 ? "" : "s", why_not_correctable(c),
        format_mm(r.flagged_rms_t_m).c_str());
  }
  if (s.n_targets == 0) {
    std::printf("  no target was corrected: no corrected RMS_T, gamma or N_bad\n");
    if (!args.per_target.empty())
      std::printf("  per-target errors written to %s\n", args.per_target.c_str());
    return;
  }
  std::printf("                                uncorrected  corrected (%s)%s\n",
              is_field_model(c.method_used) ? to_string(c.method_used) : "RRBC",
              c.n_flagged > 0
                  ? (", over the " + std::to_string(s.n_targets) + " targets corrected").c_str()
                  : "");
  std::printf("  RMS_T                         %8s mm  %8s mm\n", format_mm(s.unc_rms_t_m).c_str(),
              format_mm(s.cor_rms_t_m).c_str());
  std::printf("  max TRE                       %8s mm  %8s mm\n",
              format_mm(s.unc_max_tre_m).c_str(), format_mm(s.cor_max_tre_m).c_str());
  print_predicted_sd(c, r.calibration);
  if (r.orientation) {
    const OrientationEvaluation& o = *r.orientation;
    const bool not_better =
        std::any_of(o.correction.status.begin(), o.correction.status.end(),
                    [](StencilStatus status) { return status == StencilStatus::kNotBetterThanNone; });
    std::printf("  RMS angle (orientation)       %8.3f mrad %6.3f mrad%s\n", 1e3 * o.unc_rms_rad,
                1e3 * o.cor_rms_rad,
                not_better ? "  (not corrected: correction not better than none)" : "");
    if (o.calibration.n > 0) {
      std::printf("  angle / predicted sd          RMS %.2f (1 = honest), %.0f %% within 2 sd\n",
                  o.calibration.rms_ratio, 100.0 * o.calibration.within_2sigma);
    }
  }
  if (r.multidirectional) print_multidirectional(*r.multidirectional);
  std::printf("  gamma = (unc - cor) / unc     %.1f %%\n", 100.0 * s.gamma);
  std::printf("  N_bad (TRE got worse)         %d of %d", s.n_bad, s.n_targets);
  if (!bad.empty()) {
    std::printf(":");
    for (std::size_t k = 0; k < bad.size() && k < 10; ++k) std::printf(" %s", bad[k].c_str());
    if (bad.size() > 10) std::printf(" ...");
  }
  std::printf("\n");
  if (!args.per_target.empty())
    std::printf("  per-target errors written to %s\n", args.per_target.c_str());
}

void run_evaluate(const EvaluateArgs& args) {
  const RegistrationModel model = io::read_model_json(args.model);
  naming_file(args.model, [&] { run_evaluate_unchecked(args, model); });
}

void add_evaluate_command(CLI::App& app) {
  auto args = std::make_shared<EvaluateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "evaluate",
      "measure a model's accuracy on targets measured in both frames: TRE and RMS_T "
      "uncorrected and RRBC-corrected (paper Eq. 3, 4, 7, 8)");
  add_input_option(*cmd, "--model", args->model, "model JSON written by 'vrreg register -o'")
      ->required();
  add_input_option(*cmd, "--targets", args->targets, "measurement CSV; its target rows are used")
      ->required();
  cmd->add_option("--config", args->config,
                  "use only target rows with this configuration label (default: the model's)");
  args->interpolation.add_to(*cmd);
  args->interpolation.add_corrector_flags_to(*cmd);
  args->strategy.add_to(*cmd, false);
  add_output_option(*cmd, "--per-target", args->per_target,
                    "write per-target errors (CSV, mm) here");
  add_robot_option(*cmd, "--robot", args->robot,
                   "with --interpolation joint or auto: the robot whose joints the files give "
                   "(ur5, lwr4, ... or a robot file, its tool the marker); default: the model's");
  args->links.add_to(*cmd, "--robot; default: the links the model's robot was taken between");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the table");
  cmd->callback([args] { run_evaluate(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(20, add_evaluate_command);

}  // namespace vrreg::cli
