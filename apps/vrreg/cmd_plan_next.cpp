// SPDX-License-Identifier: Apache-2.0
// vrreg plan-next: adaptive planning (docs/adaptive.md). Given the part points, the robot and
// the fiducials measured so far, the next batch of fiducial locations where the kriging
// correction's predicted sd at the parts falls fastest, as a plan CSV (the format of `vrreg
// plan`), and whether to stop: the predicted sd at the parts now and after the batch.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "measurement_input.hpp"
#include "plan_output.hpp"
#include "plan_program_cli.hpp"
#include "robot_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/parts_csv.hpp"
#include "vrreg/io/plan_csv.hpp"
#include "vrreg/pipeline/plan_next_correction.hpp"
#include "vrreg/planning/plan_next.hpp"

namespace vrreg::cli {
namespace {

struct PlanNextArgs {
  PlanArgs plan;  ///< robot, orientation, home joints, program export, output
  std::string measured;
  std::optional<double> goal_sd_mm;
  std::optional<double> goal_floor_multiple;
  double sigma_rep_mm = 0.0;
  int batch = 8;
  int budget = 64;
  double candidate_spacing_mm = 20.0;
  double margin_mm = 20.0;
  std::string interpolation = "kriging";  ///< what the measured fiducials will be corrected with
  std::vector<double> volume_mm;  ///< x0 x1 y0 y1 z0 z1: a work volume instead of part points
  double volume_spacing_mm = 50.0;
};

// The measured fiducials and the noise of one averaged reading (the nugget's floor).
planning::MeasuredFiducials read_measured(const std::string& path, const MeasurementSet& set,
                                          std::optional<double>& noise_sd_m) {
  try {
    planning::FiducialsWithNoise m = planning::measured_fiducials(set);
    noise_sd_m = m.noise_sd_m;
    return std::move(m.fiducials);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

std::string next_sd_text(double value_m) {
  return std::isfinite(value_m) ? fmt::format("{:.4f} mm", units::m_to_mm(value_m)) : "n/a";
}

// "0.1000 mm", or "2 x the noise floor 0.0521 mm = 0.1042 mm" (floor "not known yet").
std::string goal_text(const PlanNextArgs& args, const planning::PlanNextResult& r) {
  if (!args.goal_floor_multiple) return next_sd_text(r.goal_sd_m);
  return fmt::format("{:g} x the noise floor ", *args.goal_floor_multiple) +
         (std::isfinite(r.noise_floor_m)
              ? next_sd_text(r.noise_floor_m) + " = " + next_sd_text(r.goal_sd_m)
              : std::string("(not known yet: no repeat readings)"));
}

std::vector<std::string> next_comments(const PlanNextArgs& args, const PlanSetup& setup,
                                       const planning::PlanNextResult& r) {
  std::vector<std::string> c;
  c.push_back("vrreg plan-next: adaptive fiducial batch (docs/adaptive.md)");
  c.push_back("robot: " + setup.chain.name());
  c.push_back(fmt::format("measured fiducials: {}", r.n_measured));
  c.push_back("goal sd at the parts: " + goal_text(args, r));
  c.push_back(fmt::format("batch: {}, budget: {}", args.batch, args.budget));
  c.push_back(fmt::format("candidate spacing: {:.3f} mm, margin: {:.3f} mm",
                          args.candidate_spacing_mm, args.margin_mm));
  c.push_back(std::string("design: ") + (r.space_filling ? "space-filling (greedy maximin)"
                                                         : "greedy kriging variance reduction"));
  c.push_back("predicted sd at the parts now: " + next_sd_text(r.rms_sd_now_m) + " (" +
              r.sd_method + ")");
  if (!r.sd_note.empty()) c.push_back("kriging's prediction used: " + r.sd_note);
  c.push_back("predicted sd at the parts after the batch: " + next_sd_text(r.rms_sd_after_m));
  for (const std::string& note : setup.notes) c.push_back("note: " + note);
  return c;
}

nlohmann::json next_json(const planning::PlanNextResult& r) {
  auto number = [](double value_m) {
    return std::isfinite(value_m) ? nlohmann::json(units::m_to_mm(value_m)) : nlohmann::json();
  };
  nlohmann::json parts = nlohmann::json::array();
  for (std::size_t i = 0; i < r.parts.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    parts.push_back(
        {{"point", r.parts[i].name},
         {"sd_now_mm", r.has_model ? number(r.part_sd_now_m(k)) : nlohmann::json()},
         {"sd_after_mm", r.has_model ? number(r.part_sd_after_m(k)) : nlohmann::json()}});
  }
  return {{"decision", planning::to_string(r.decision)},
          {"reason", r.reason},
          {"n_measured", r.n_measured},
          {"n_planned", r.locations.size()},
          {"n_candidates", r.n_candidates},
          {"space_filling", r.space_filling},
          {"goal_sd_mm", number(r.goal_sd_m)},
          {"noise_floor_mm", number(r.noise_floor_m)},
          {"predicted_sd_now_mm", number(r.rms_sd_now_m)},
          {"predicted_sd_after_mm", number(r.rms_sd_after_m)},
          {"predicted_by", r.has_model ? nlohmann::json(r.sd_method) : nlohmann::json()},
          {"prediction_note", r.sd_note.empty() ? nlohmann::json() : nlohmann::json(r.sd_note)},
          {"path_mm", units::m_to_mm(r.path_m)},
          {"parts", parts}};
}

void run_plan_next_unchecked(const PlanNextArgs& args) {
  VRREG_THROW_UNLESS(args.plan.monitor_program.empty(),
                     "--monitor-program: plan-next plans no monitor points");
  PlanSetup setup = make_plan_setup(args.plan);
  VRREG_THROW_UNLESS(args.plan.parts.empty() != args.volume_mm.empty(),
                     "give the part points as --parts FILE or as --volume (one of them)");
  std::vector<io::PartRecord> records;
  if (!args.volume_mm.empty()) {
    for (const double v : args.volume_mm)
      VRREG_THROW_UNLESS(std::isfinite(v), "--volume: values must be finite");
    const auto& v = args.volume_mm;
    setup.parts = planning::volume_part_points(
        units::mm_to_m(1.0) * Eigen::Vector3d(v[0], v[2], v[4]),
        units::mm_to_m(1.0) * Eigen::Vector3d(v[1], v[3], v[5]),
        units::mm_to_m(args.volume_spacing_mm));
  } else {
    records = io::read_parts_csv(args.plan.parts);
    for (const io::PartRecord& r : records) setup.parts.push_back({r.point, r.robot_m});
  }

  planning::PlanNextOptions options;
  VRREG_THROW_UNLESS(args.goal_sd_mm.has_value() != args.goal_floor_multiple.has_value(),
                     "give the goal as --goal-sd-mm or as --goal-floor-multiple (one of them)");
  if (args.goal_sd_mm) options.goal_sd_m = units::mm_to_m(*args.goal_sd_mm);
  options.goal_floor_multiple = args.goal_floor_multiple;
  options.sigma_rep_m = units::mm_to_m(args.sigma_rep_mm);
  options.batch_size = args.batch;
  options.budget = args.budget;
  options.candidate_spacing_m = units::mm_to_m(args.candidate_spacing_mm);
  options.margin_m = units::mm_to_m(args.margin_mm);
  options.arm = setup.options.arm;
  planning::MeasuredFiducials measured;
  if (!args.measured.empty()) {
    MeasurementSet set = read_measurements(args.measured);
    measured = read_measured(args.measured, set, options.noise_sd_m);
    const InterpolationMethod method = parse_interpolation_method(args.interpolation);
    if (method != InterpolationMethod::kKriging) {
      RegisterOptions register_options;
      register_options.interpolation.method = method;
      register_options.robot = setup.chain;  // the joints in the file are on the plan's chain
      try {
        options.correction_sd = correction_sd_at_parts(std::move(set), register_options);
      } catch (const InputError& e) {
        throw InputError(args.measured + ": " + e.what());
      }
    }
  }

  options.validate(setup.chain);
  planning::PlanNextResult r;
  try {
    r = planning::plan_next(setup.chain, setup.parts, measured, options);
  } catch (const InputError& e) {
    // The options are valid: what fails past them is the part points (checked when read) or
    // the measured fiducials (too few distinct, collinear, coplanar): name the file.
    if (args.measured.empty()) throw;
    std::string what = e.what();
    if (what.starts_with("plan next: ")) what.erase(0, 11);
    throw InputError("plan next: " + args.measured + ": " + what);
  }
  if (!r.ok() && records.empty()) {
    throw InputError("plan next: --volume: " + r.message +
                     ". Check that the volume is in the robot base frame, or change --rpy-deg, "
                     "--home-deg or --psi-deg (see vrreg ik)");
  }
  if (!r.ok()) {
    throw io::FileError(args.plan.parts, records.front().line,
                        r.message +
                            ". Check that the part points are in the robot base frame, or "
                            "change --rpy-deg, --home-deg or --psi-deg (see vrreg ik)");
  }
  planning::PlanResult plan;
  plan.parts = r.parts;
  plan.locations = r.locations;
  std::vector<io::OutputFile> outputs;
  if (!r.locations.empty()) {
    if (!args.plan.export_format.empty())
      outputs.push_back({args.plan.program, plan_program(args.plan, plan)});
    if (!args.plan.output.empty()) {
      outputs.push_back(
          {args.plan.output, io::format_plan_csv(plan_rows(plan), next_comments(args, setup, r))});
    }
  }
  io::write_files_atomically(outputs);
  if (args.plan.json) {
    print_json(next_json(r));
    return;
  }
  std::printf("measured fiducials: %lld; reachable candidates: %lld\n",
              static_cast<long long>(r.n_measured), static_cast<long long>(r.n_candidates));
  std::printf("predicted sd at the parts now: %s; after the batch: %s (goal %s)%s\n",
              next_sd_text(r.rms_sd_now_m).c_str(), next_sd_text(r.rms_sd_after_m).c_str(),
              goal_text(args, r).c_str(),
              r.has_model && r.sd_method != "kriging" ? (", predicted by " + r.sd_method).c_str()
                                                      : "");
  if (!r.sd_note.empty()) {
    std::printf("predicted by kriging: the %s correction gives none yet (%s)\n",
                args.interpolation.c_str(), r.sd_note.c_str());
  }
  if (!r.locations.empty()) {
    std::printf("next batch: %zu locations (%s), path %.1f mm%s\n", r.locations.size(),
                r.space_filling ? "space-filling" : "greedy variance reduction",
                units::m_to_mm(r.path_m),
                args.plan.output.empty() ? "" : (", written to " + args.plan.output).c_str());
  }
  std::printf("%s: %s\n", r.decision == planning::PlanNextDecision::kStop ? "STOP" : "CONTINUE",
              r.reason.c_str());
}

void run_plan_next(const PlanNextArgs& args) {
  try {
    run_plan_next_unchecked(args);
  } catch (const io::FileError&) {
    throw;
  } catch (const InputError& e) {
    const std::string what = e.what();
    throw InputError(what.starts_with("plan next: ") ? what : "plan next: " + what);
  }
}

void add_plan_next_command(CLI::App& app) {
  auto args = std::make_shared<PlanNextArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plan-next",
      "adaptive planning: the next batch of fiducial locations where the kriging correction's "
      "predicted sd at the part points falls fastest, and whether to stop (docs/adaptive.md)");
  add_input_option(*cmd, "--parts", args->plan.parts,
                   "CSV of part points: point,robot_x_mm,robot_y_mm,robot_z_mm (robot base frame), "
                   "or a measurement CSV whose target rows are the part points (or give --volume)");
  cmd->add_option("--volume", args->volume_mm,
                  "a work volume instead of --parts: X0 X1 Y0 Y1 Z0 Z1 in mm (robot base frame); "
                  "the part points are a lattice of --volume-spacing-mm filling it")
      ->expected(6)
      ->delimiter(',')
      ->excludes("--parts");
  cmd->add_option("--volume-spacing-mm", args->volume_spacing_mm,
                  "spacing of the part points' lattice in --volume, mm")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  add_robot_option(*cmd, "--robot", args->plan.robot,
                   "ur5, lwr4 (defaults from the simulated test bed), ur3, ur10, ur5e, or a robot "
                   "file (URDF, or JSON/YAML)")
      ->required();
  args->plan.links.add_to(*cmd, "--robot");
  add_input_option(*cmd, "--measured", args->measured,
                   "measurement CSV of the fiducials measured so far (none: the first batch)");
  cmd->add_option("--goal-sd-mm", args->goal_sd_mm,
                  "goal: predicted RMS_T at the part points, mm (the root mean square of the "
                  "corrected parts' predicted sd)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--goal-floor-multiple", args->goal_floor_multiple,
                  "goal: this multiple of the noise floor sqrt(3 (sigma_rep^2 + sigma_opt^2/K)) "
                  "from the measured file's repeat readings (instead of --goal-sd-mm)")
      ->check(CLI::PositiveNumber)
      ->excludes("--goal-sd-mm");
  cmd->add_option("--sigma-rep-mm", args->sigma_rep_mm,
                  "robot repeatability in mm, for the noise floor (UR5 0.1, LWR 4+ 0.05; 0: the "
                  "floor counts the sensor only)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--batch", args->batch, "locations per batch")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--budget", args->budget, "most fiducials in all, measured and planned")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  not_a_file(*cmd,
             cmd->add_option("--interpolation", args->interpolation,
                             "what the measured fiducials will be corrected with: its predicted "
                             "sd at the parts is judged against the goal (joint needs the "
                             "joints in --measured; the batch is still kriging's best)")
                 ->capture_default_str()
                 ->check(CLI::IsMember({"kriging", "joint", "rbf", "trilinear", "auto"})));
  cmd->add_option("--candidate-spacing-mm", args->candidate_spacing_mm,
                  "spacing of the candidate lattice over the parts' bounding box, mm")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--margin-mm", args->margin_mm,
                  "the candidate box extends this far beyond the part points, mm")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--tool-mm", args->plan.tool_mm,
                  "TCP (tracked sphere) offset X Y Z in the flange frame, mm")
      ->expected(3);
  cmd->add_option("--rpy-deg", args->plan.rpy_deg,
                  "fixed TCP orientation ROLL PITCH YAW in deg, R = Rz(yaw) Ry(pitch) Rx(roll)")
      ->expected(3);
  cmd->add_option("--psi-deg", args->plan.psi_deg, "LWR arm angle psi in deg for every location");
  cmd->add_option("--home-deg", args->plan.home_deg,
                  "joints Q1 ... QN in deg: each part point takes the IK solution nearest these")
      ->expected(1, kinematics::kMaxJoints);
  not_a_file(*cmd, cmd->add_option("--norm", args->plan.norm,
                                   "joint-space distance for 'nearest': l2 (paper) or linf")
                       ->check(CLI::IsMember({"l2", "linf"})));
  add_program_options(*cmd, args->plan);
  add_output_option(*cmd, "-o,--output", args->plan.output,
                    "write the batch as a plan CSV here (not written on STOP)");
  cmd->add_flag("--json", args->plan.json, "print one JSON object instead of the summary");
  cmd->callback([args] { run_plan_next(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(51, add_plan_next_command);

}  // namespace vrreg::cli
