// SPDX-License-Identifier: Apache-2.0
// vrreg register: rigid registration of fiducials (Eq. 2), the rigid-body condition (Eq. 1),
// noise (Eq. 9) and the RRBC fiducial corrections (Eq. 6), saved as a model for evaluate/correct;
// with --strategy, Procedure 2's handling of arm configurations (section 4.4, strategy_cli.hpp).
#include <cstdio>
#include <iostream>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "field_model_cli.hpp"
#include "marker_offset_cli.hpp"
#include "measurement_input.hpp"
#include "robot_cli.hpp"
#include "strategy_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/result_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::cli {
namespace {

struct RegisterArgs {
  std::string fiducials;
  std::optional<int> config;
  bool scale = false;
  bool robust = false;
  std::optional<double> sigma_rep_mm;
  InterpolationFlags interpolation;
  StrategyFlags strategy;
  std::string output;
  bool json = false;
  bool exact_sigma_l = false;
  MarkerOffsetFlags marker_offset;
  std::optional<std::string> lost_motion;  ///< as given; auto when not
};

void run_register_unchecked(const RegisterArgs& args);

// Degenerate geometry and the like come from the library without a file name.
void run_register(const RegisterArgs& args) {
  naming_file(args.fiducials, [&] { run_register_unchecked(args); });
}

RegisterOptions register_options(const RegisterArgs& args) {
  RegisterOptions options;
  options.config = args.config;
  options.registration.estimate_scale = args.scale;
  if (args.robust) options.robust = OutlierOptions{};
  if (args.sigma_rep_mm) options.sigma_rep_m = units::mm_to_m(*args.sigma_rep_mm);
  options.interpolation = args.interpolation.settings();
  options.procedure2 = register_procedure2(args.strategy);
  options.sigma_l.force_exact = args.exact_sigma_l;
  options.lost_motion = parse_lost_motion_mode(args.lost_motion.value_or("auto"));
  if (!args.marker_offset.enabled() && !args.marker_offset.robot.empty()) {
    // the joint-space field model
    options.robot = robot_from_args(args.marker_offset.robot, {}, args.marker_offset.links.links());
  }
  return options;
}

void print_robust(const RobustReport& report) {
  const OutlierDetection& d = report.detection;
  std::printf("  robust check                  %zu outlier%s of %d fiducials judged "
              "(bound %.2f sigma, sigma = %s mm from %s)\n",
              report.rejected.size(), report.rejected.size() == 1 ? "" : "s", d.n_judged,
              d.threshold_sigmas, format_mm(d.sigma_m).c_str(),
              d.scale_is_noise ? "sigma_noise" : "the spread of the deviations");
  for (const RejectedFiducial& r : report.rejected) {
    std::printf("    %-27s %s mm = %.1f sigma off its neighbours' prediction; %s\n",
                (r.point + (r.config ? " (config " + std::to_string(*r.config) + ")" : "")).c_str(),
                format_mm(r.deviation_m).c_str(), r.sigmas,
                r.filled ? "correction filled from neighbours"
                         : "dropped (too few neighbours): grid interpolation falls back to "
                           "scattered");
  }
}

void run_register_unchecked(const RegisterArgs& args) {
  const RegisterOptions options = register_options(args);
  options.validate();  // flag combinations before reading the file
  args.marker_offset.check();
  if (args.marker_offset.enabled()) {  // hand-eye registration: its own report (marker_offset_cli)
    run_register_with_marker_offset(args.fiducials, args.marker_offset, options, args.output,
                                    args.json);
    return;
  }
  const RegisterResult result =
      register_fiducials(read_measurements(args.fiducials), options);
  const RegistrationModel& model = result.model;
  const RegistrationResult& reg = result.registration;
  const RigidBodyStatistics& rb = result.rigid_body;
  const std::optional<planning::Strategy2Summary>& relabelled = result.relabelled;
  const std::size_t n_registered = result.n_registered;
  const std::optional<double>& sigma_opt = result.noise.sigma_opt_m;
  const std::optional<double>& sigma_noise = result.noise.sigma_noise_m;
  const std::optional<double>& rho_value = result.noise.rho;

  if (!args.output.empty()) io::write_model_json(args.output, model);

  const Eigen::Matrix3d& r = model.T_robot_sensor.rotation;
  if (args.json) {
    nlohmann::json j = io::register_json(result);
    j["source"] = args.fiducials;
    j["config"] = args.config ? nlohmann::json(*args.config) : nlohmann::json(nullptr);
    if (args.sigma_rep_mm) j["sigma_rep_mm"] = *args.sigma_rep_mm;  // as given
    // Asked for by name: said even when it did not enter (register_json holds it when it did).
    if (args.lost_motion && model.corrector && model.corrector->lost_motion())
      j["lost_motion"] = io::lost_motion_result_json(*model.corrector->lost_motion());
    j["model"] = args.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(args.output);
    print_json(j);
    return;
  }
  std::printf("registered %zu fiducials from %s%s\n", n_registered, args.fiducials.c_str(),
              args.config ? (" (config " + std::to_string(*args.config) + ")").c_str() : "");
  print_strategy(model, relabelled);
  std::printf("  rotation R (sensor -> robot)  [% .9f % .9f % .9f]\n", r(0, 0), r(0, 1), r(0, 2));
  std::printf("                                [% .9f % .9f % .9f]\n", r(1, 0), r(1, 1), r(1, 2));
  std::printf("                                [% .9f % .9f % .9f]\n", r(2, 0), r(2, 1), r(2, 2));
  std::printf("  translation tau               %s mm\n",
              format_mm3(model.T_robot_sensor.translation_m).c_str());
  if (args.scale) std::printf("  scale                         %.9f\n", model.T_robot_sensor.scale);
  std::printf(
      "  FRE                           %s mm  (fit residual, not target accuracy: run evaluate)\n",
      format_mm(reg.fre_m).c_str());
  if (result.sigma_l_sampling.sampled) {
    const SigmaLSampling& s = result.sigma_l_sampling;
    std::printf(
        "  sigma_L                       %s mm  (SAMPLED: %lld of %lld pairs, seed %llu; 95%% "
        "interval %s to %s mm; --exact-sigma-l for all pairs)\n",
        format_mm(rb.sigma_l_m).c_str(), static_cast<long long>(s.pairs_sampled),
        static_cast<long long>(s.pairs_total), static_cast<unsigned long long>(s.seed),
        format_mm(s.sigma_l_low_m, 5).c_str(), format_mm(s.sigma_l_high_m, 5).c_str());
  } else {
    std::printf("  sigma_L                       %s mm  (rigid-body condition over %lld pairs)\n",
                format_mm(rb.sigma_l_m).c_str(), static_cast<long long>(rb.pairs));
  }
  if (sigma_opt) {
    std::printf("  sigma_opt                     %s mm  (per axis, from repeat readings)\n",
                format_mm(*sigma_opt).c_str());
  }
  if (sigma_noise) {
    std::printf("  sigma_noise                   %s mm  (sigma_rep = %s mm%s)\n",
                format_mm(*sigma_noise).c_str(),
                format_mm(units::mm_to_m(args.sigma_rep_mm.value_or(0.0))).c_str(),
                args.sigma_rep_mm ? "" : ", not given: use --sigma-rep-mm");
  }
  if (rho_value) {
    std::printf("  rho = sigma_L / sigma_noise   %.2f  %s%s\n", *rho_value,
                *rho_value > kRhoThreshold
                    ? "(> 2.5: systematic error dominates, RRBC should help)"
                    : "(<= 2.5: noise dominates, RRBC is not expected to help)",
                args.sigma_rep_mm ? "" : "; an upper bound without --sigma-rep-mm");
  }
  std::printf("  spread (principal axes)       %s mm\n", format_mm3(reg.spread_m, 1).c_str());
  if (result.robust) print_robust(*result.robust);
  if (result.cross_validation) {
    print_cross_validation(*result.cross_validation);
    std::printf("  interpolation stored          %s (evaluate's and correct's default)\n",
                to_string(model.interpolation.method));
  }
  if (model.corrector && model.corrector->guard()) print_guard(*model.corrector->guard());
  // The term when it entered, or when --lost-motion asked for it: other cells print what they did.
  if (model.corrector && model.corrector->lost_motion() &&
      (model.corrector->lost_motion()->applied || args.lost_motion))
    print_lost_motion(*model.corrector->lost_motion());
  if (model.orientation_corrector) print_orientation_field(*model.orientation_corrector);
  if (!args.output.empty()) std::printf("  model written to %s\n", args.output.c_str());
}

void add_register_command(CLI::App& app) {
  auto args = std::make_shared<RegisterArgs>();
  CLI::App* cmd = app.add_subcommand(
      "register",
      "register the fiducials of a measurement file (sensor -> robot, paper Eq. 2) "
      "and compute their RRBC corrections (Eq. 6)");
  add_input_option(*cmd, "--fiducials", args->fiducials,
                   "measurement CSV; its fiducial rows are used")
      ->required();
  cmd->add_option("--config", args->config, "use only rows with this configuration label");
  cmd->add_flag("--scale", args->scale, "also fit a uniform scale (off in the paper)");
  cmd->add_flag("--robust", args->robust,
                "find fiducials whose correction disagrees with their neighbours' (a displaced or "
                "swapped marker), register without them and fill their corrections from the "
                "neighbours (docs/outliers.md)");
  cmd->add_option("--sigma-rep-mm", args->sigma_rep_mm,
                  "robot repeatability in mm, for sigma_noise and rho (UR5 0.1, LWR 4+ 0.05)")
      ->check(CLI::NonNegativeNumber);
  args->interpolation.add_to(*cmd);
  args->strategy.add_to(*cmd, true);
  args->marker_offset.add_to(*cmd);
  add_output_option(*cmd, "-o,--output", args->output, "write the model (JSON) here");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the table");
  not_a_file(*cmd, cmd->add_option("--lost-motion", args->lost_motion,
                  "the corrector's lost-motion term (gear backlash; needs joints, --robot and "
                  "approach directions: from_q columns or rows in visiting order): auto (enters "
                  "when cross-validation finds it clearly better), on or off "
                  "(docs/joint-space-model.md)"))
      ->check(CLI::IsMember({"auto", "on", "off"}));
  cmd->add_flag("--exact-sigma-l", args->exact_sigma_l,
                "sigma_L over all pairs even above 20000 fiducials (quadratic time; by default "
                "larger sets use 10^7 sampled pairs and say so)");
  cmd->callback([args] { run_register(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(10, add_register_command);

}  // namespace vrreg::cli
