// SPDX-License-Identifier: Apache-2.0
// vrreg correct: RRBC-corrected robot-frame positions for points measured by the sensor
// (Eq. 7, 8, then mapped with {R, tau}): what the robot should be commanded to.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "field_model_cli.hpp"
#include "measurement_input.hpp"
#include "robot_cli.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/result_json.hpp"
#include "vrreg/io/results_csv.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::cli {
namespace {

struct CorrectArgs {
  std::string model;
  std::string points;
  std::optional<int> config;
  InterpolationFlags interpolation;
  std::string output;
  std::string robot;
  RobotLinkFlags links;
  bool json = false;
  std::optional<double> angle_sd_limit_mrad;
};

void run_correct_unchecked(const CorrectArgs& args, const RegistrationModel& model) {
  io::CsvReadOptions read_options;
  read_options.require_robot = false;  // points to correct need only their sensor position
  CorrectOptions options;
  options.config = args.config;
  options.interpolation = args.interpolation.choice();
  options.refit = args.interpolation.refit;
  options.extrapolate = args.interpolation.extrapolate;
  options.exact = args.interpolation.exact;
  if (!args.robot.empty()) {
    const kinematics::SerialChain* remembered = model.robot ? &*model.robot : nullptr;
    options.robot = robot_from_args(args.robot, {}, args.links.links(remembered));
  }
  const MeasurementSet points = read_measurements(args.points, read_options);
  CorrectResult r = correct(model, points, options);
  if (r.orientation && args.angle_sd_limit_mrad) {
    r.orientation->sd_limit_rad = 1e-3 * *args.angle_sd_limit_mrad;
  }
  const TargetCorrection& c = r.correction;
  // A file may carry orientations for other reasons: corrected positions are still right, but
  // the orientations are not corrected, and the user is told so rather than left to assume.
  const bool points_have_orientations =
      std::any_of(points.locations.begin(), points.locations.end(),
                  [](const Location& l) { return l.q_sensor_marker.has_value(); });
  if (points_have_orientations && !model.has_fiducial_orientations()) {
    std::cerr << "vrreg: warning: " << args.points
              << ": the points' orientations (sensor_q*) are not corrected: the model's "
                 "fiducials carry no measured and commanded orientations (sensor_q*, "
                 "robot_q*); positions only\n";
  }
  io::write_corrected_csv(args.output, r, args.model, args.points);
  const std::size_t n_points = r.names.size();

  if (args.json) {
    nlohmann::json j = io::correct_json(r);
    j["output"] = args.output;
    print_json(j);
    return;
  }
  std::printf("corrected %zu points from %s with model %s\n", n_points, args.points.c_str(),
              args.model.c_str());
  if (r.cross_validation) print_cross_validation(*r.cross_validation);
  std::printf("  interpolation                 %s: %s\n", to_string(c.method_used),
              c.layout.c_str());
  if (c.guard && !c.guard->applied) print_guard(*c.guard);
  print_predicted_sd(c, std::nullopt);
  if (r.orientation) print_orientation_correction(*r.orientation);
  if (c.n_flagged > 0) {
    std::printf(
        "  not correctable               %d points (%s; status column says why; robot_* holds "
        "the uncorrected mapping)\n",
        c.n_flagged, why_not_correctable(c));
  }
  std::printf("  robot-frame positions (mm) written to %s\n", args.output.c_str());
}

void run_correct(const CorrectArgs& args) {
  const RegistrationModel model = io::read_model_json(args.model);
  naming_file(args.model, [&] { run_correct_unchecked(args, model); });
}

void add_correct_command(CLI::App& app) {
  auto args = std::make_shared<CorrectArgs>();
  CLI::App* cmd = app.add_subcommand(
      "correct",
      "RRBC-correct points measured by the sensor and map them to the robot frame "
      "(paper Eq. 7, 8)");
  add_input_option(*cmd, "--model", args->model, "model JSON written by 'vrreg register -o'")
      ->required();
  add_input_option(*cmd, "--points", args->points,
                   "measurement CSV; its target rows are corrected (robot columns optional)")
      ->required();
  cmd->add_option("--config", args->config, "use only rows with this configuration label");
  args->interpolation.add_to(*cmd);
  args->interpolation.add_corrector_flags_to(*cmd);
  add_output_option(*cmd, "-o,--output", args->output, "write corrected positions (CSV, mm) here")
      ->required();
  add_robot_option(*cmd, "--robot", args->robot,
                   "with --interpolation joint or auto: the robot whose joints the file gives "
                   "(ur5, lwr4, ... or a robot file, its tool the marker); default: the model's");
  args->links.add_to(*cmd, "--robot; default: the links the model's robot was taken between");
  cmd->add_flag("--json", args->json, "print a JSON summary instead of the table");
  cmd->add_option("--angle-sd-limit-mrad", args->angle_sd_limit_mrad,
                  "flag points whose predicted orientation sd is above this, mrad "
                  "(angle_sd_over_limit); default: the fiducials' uncorrected RMS angle")
      ->check(CLI::PositiveNumber);
  cmd->callback([args] { run_correct(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(30, add_correct_command);

}  // namespace vrreg::cli
