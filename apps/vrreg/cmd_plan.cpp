// SPDX-License-Identifier: Apache-2.0
// vrreg plan: Procedure 1, "where to measure" (paper section 6, Fig. 16). For each part point a
// cube of fiducials on a grid (placement tolerance +-S, spacing A), the d_min > 2.5 sigma_noise
// check (Eq. 9), joints for every location nearest its part point's, and a visiting order; the
// plan is written as a CSV a robot program (or `vrreg simulate --plan`) can follow.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "plan_output.hpp"
#include "plan_program_cli.hpp"
#include "robot_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/parts_csv.hpp"
#include "vrreg/io/plan_csv.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/planning/monitor_points.hpp"
#include "vrreg/planning/offset_poses.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::cli {
namespace {

using kinematics::ChainFamily;

// Default SIR standoff along the flange z axis for robots without a test bed or tool [m].
constexpr double kDefaultToolOffsetM = 0.06;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// --approach-from: "+" or "-" for every joint, or one sign per joint ("+,+,-,+,+,+").
planning::ApproachOptions approach_options(const PlanArgs& args,
                                           const kinematics::SerialChain& chain) {
  planning::ApproachOptions approach;
  std::vector<double> signs;
  std::string text = args.approach_from;
  text.erase(std::remove(text.begin(), text.end(), ' '), text.end());
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    VRREG_THROW_UNLESS(item == "+" || item == "-",
                       "--approach-from: '" << args.approach_from
                                            << "': give + or - for every joint, or one per joint "
                                               "separated by commas (e.g. +,+,-,+,+,+)");
    signs.push_back(item == "+" ? 1.0 : -1.0);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const int n = chain.n_joints();
  if (signs.size() == 1) signs.assign(static_cast<std::size_t>(n), signs.front());
  VRREG_THROW_UNLESS(static_cast<int>(signs.size()) == n,
                     "--approach-from: robot '" << chain.name() << "' has " << n << " joints, got "
                                                << signs.size() << " directions");
  approach.direction = Eigen::Map<const Eigen::VectorXd>(signs.data(), n);
  approach.offset_rad = units::deg_to_rad(args.approach_offset_deg);
  approach.validate(chain);
  return approach;
}

// Via points before every location (offset poses and monitor points too); a location too near a
// joint limit for its via point names its part point's line.
void add_vias(const PlanArgs& args, const PlanSetup& setup,
              const std::vector<io::PartRecord>& records, planning::PlanResult& plan) {
  try {
    planning::add_approach_vias(setup.chain, plan, setup.options.approach);
  } catch (const InputError& e) {
    for (const planning::PlannedLocation& l : plan.locations) {
      if (l.via_q_rad || l.part < 0 || static_cast<std::size_t>(l.part) >= records.size()) {
        continue;
      }
      throw io::FileError(args.parts, records[static_cast<std::size_t>(l.part)].line,
                          std::string("plan: ") + e.what());
    }
    throw;
  }
}

// The robot, the planning options and where their defaults came from.
PlanSetup make_setup(const PlanArgs& args) {
  PlanSetup s{robot_from_args(args.robot, args.tool_mm, args.links.links()), {}, {}, {}};
  const std::string name = lower(args.robot);
  std::optional<simulation::Testbed> testbed;
  if (name == "ur5" || name == "lwr4") testbed = simulation::testbed_by_name(name);
  if (args.tool_mm.empty()) {
    if (testbed) {
      s.chain = s.chain.with_tool(testbed->nominal.T_flange_tcp());
      s.notes.push_back("tool offset: the simulated " + name + " test bed's");
    } else if (s.chain.T_flange_tcp().matrix() == Eigen::Matrix4d::Identity()) {
      s.chain =
          s.chain.with_tool(Eigen::Isometry3d(Eigen::Translation3d(0, 0, kDefaultToolOffsetM)));
      s.notes.push_back("tool offset: default 60 mm along the flange z axis (give --tool-mm)");
    }
  }
  planning::PlanOptions& o = s.options;
  o.halfwidth_m = units::mm_to_m(args.halfwidth_mm);
  o.spacing_m = units::mm_to_m(args.spacing_mm);
  VRREG_THROW_UNLESS(std::isfinite(args.sigma_noise_mm.value_or(1.0)),
                     "--sigma-noise-mm is not a finite number");
  if (args.sigma_noise_mm) {
    o.sigma_noise_m = units::mm_to_m(*args.sigma_noise_mm);
  } else if (testbed && s.chain.family() == ChainFamily::kLwr) {
    o.sigma_noise_m = planning::kPaperKukaSigmaNoiseM;
    s.notes.push_back("sigma_noise: 0.077 mm, the paper's KUKA LWR 4+ value (section 5.2)");
  } else {
    o.sigma_noise_m = planning::kPaperSigmaNoiseM;
    s.notes.push_back("sigma_noise: 0.114 mm, the paper's UR5 value (Table 1, A1)");
  }
  o.force = args.force;
  o.arm.norm = args.norm == "linf" ? kinematics::JointNorm::kLinf : kinematics::JointNorm::kL2;
  if (!args.rpy_deg.empty()) {
    check_finite(args.rpy_deg, "--rpy-deg");
    o.arm.R_base_tcp = kinematics::rotation_from_rpy(units::deg_to_rad(args.rpy_deg[0]),
                                                     units::deg_to_rad(args.rpy_deg[1]),
                                                     units::deg_to_rad(args.rpy_deg[2]));
  } else if (testbed) {
    o.arm.R_base_tcp = testbed->tcp_rotation;
    s.notes.push_back("tool orientation: the simulated " + name + " test bed's");
  } else {
    s.notes.push_back("tool orientation: pointing down (rpy 180 0 0 deg; give --rpy-deg)");
  }
  if (args.psi_deg) {
    VRREG_THROW_UNLESS(std::isfinite(*args.psi_deg), "--psi-deg is not a finite number");
    VRREG_THROW_UNLESS(
        s.chain.family() == ChainFamily::kLwr,
        "--psi-deg applies to 7-joint arms (lwr4); robot '" << s.chain.name() << "' has none");
    o.arm.psi_rad = units::deg_to_rad(*args.psi_deg);
  } else if (testbed && s.chain.family() == ChainFamily::kLwr) {
    o.arm.psi_rad = testbed->arm_angle_rad;
    s.notes.push_back("arm angle psi: the simulated " + name + " test bed's");
  }
  if (!args.home_deg.empty()) {
    check_finite(args.home_deg, "--home-deg");
    VRREG_THROW_UNLESS(static_cast<int>(args.home_deg.size()) == s.chain.n_joints(),
                       "--home-deg: robot '" << s.chain.name() << "' has " << s.chain.n_joints()
                                             << " joints, got " << args.home_deg.size());
    kinematics::JointVector home(s.chain.n_joints());
    for (int i = 0; i < home.size(); ++i) {
      home(i) = units::deg_to_rad(args.home_deg[static_cast<std::size_t>(i)]);
    }
    o.arm.home_q_rad = home;
  } else if (testbed) {
    o.arm.home_q_rad = testbed->home_q_rad;
    s.notes.push_back("home joints: the simulated " + name + " test bed's");
  }
  if (!args.approach_from.empty()) o.approach = approach_options(args, s.chain);
  return s;
}

// Monitor points, with what they cannot see and how long a check takes on the robot.
void add_monitor_notes(const PlanArgs& args, planning::PlanResult& plan, PlanSetup& setup) {
  const planning::MonitorChoice choice = planning::add_monitor_points(plan, args.monitor);
  setup.notes.push_back(
      "monitor points: " + std::to_string(args.monitor) +
      " fiducial locations spread over the volume, as 'monitor-*' (role monitor), read in " +
      std::to_string(args.monitor_visits) +
      " visits at registration and at every check (vrreg check, docs/monitoring.md)");
  if (choice.coplanar) {
    setup.notes.push_back(
        "monitor points on one plane (" + format_fixed(1e3 * choice.off_plane_rms_m, 1) +
        " mm RMS off it): a change along its normal that is zero on it (the robot tilting or "
        "stretching out of that plane) moves none of them; " +
        (args.monitor < planning::kDefaultMonitorPoints
             ? std::string("4 off one plane see it (--monitor without a count)")
             : std::string("the plan's fiducials offer none off it")));
  }
  planning::ProgramOptions program;
  if (args.repeats > 0) program.repeats = args.repeats;
  const planning::ProgramDuration check = planning::program_duration(
      planning::monitor_program_locations(plan, args.monitor_visits), program);
  setup.notes.push_back(fmt::format(
      "a check on the robot (--monitor-program): {} stops, about {:.1f} min: {:.0f} s of joint "
      "moves (movej v {:.2f} rad/s, a {:.2f} rad/s^2), {:.0f} s settling, {:.0f} s for {} "
      "readings per stop at {:.0f} Hz (the operator's confirmations not counted)",
      check.stops, check.total_s() / 60.0, check.motion_s, program.joint_speed_rad_s,
      program.joint_accel_rad_s2, check.settle_s, check.readings_s, program.repeats,
      planning::kTrackerRateHz));
}

void run_plan_unchecked(const PlanArgs& args) {
  PlanSetup setup = make_setup(args);
  const std::vector<io::PartRecord> records = io::read_parts_csv(args.parts);
  for (const io::PartRecord& r : records) setup.parts.push_back({r.point, r.robot_m});

  // Eq. 9 first, with the option that overrides it named.
  const planning::CubeGeometry cube =
      planning::cube_geometry(setup.options.halfwidth_m, setup.options.spacing_m);
  try {
    (void)planning::check_dmin(cube.d_min_m(), setup.options.sigma_noise_m, setup.options.force);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (--force plans anyway)");
  }
  // Via points come last, once every location (offset poses, monitor points) is in the plan.
  planning::PlanOptions without_vias = setup.options;
  without_vias.approach = {};
  planning::PlanResult plan = planning::make_plan(setup.chain, setup.parts, without_vias);
  if (!plan.ok()) {
    // The line of the first part point that (or one of whose fiducials) cannot be reached.
    const int part = plan.unreachable.empty() ? -1 : plan.unreachable.front().part;
    throw io::FileError(args.parts, part < 0 ? 0 : records[static_cast<std::size_t>(part)].line,
                        plan.message +
                            ". Check that the part points are in the robot base frame, or change "
                            "--rpy-deg, --home-deg or --psi-deg (see vrreg ik)");
  }
  if (args.offset_tilt_deg) {  // hand-eye: tilts about two axes make the marker offset observable
    const planning::OffsetPoseSummary poses = planning::add_offset_poses(
        setup.chain, plan, setup.options.arm, units::deg_to_rad(*args.offset_tilt_deg));
    setup.notes.push_back(
        "offset poses: " + std::to_string(poses.n_added) + " fiducials 'offset-*' first, the "
        "tool tilted by +-" + format_fixed(*args.offset_tilt_deg, 1) +
        " deg about its x and y axes at the volume's corners and centre (" +
        std::to_string(poses.n_unreachable) +
        " unreachable, left out); register with --estimate-marker-offset");
  }
  if (args.monitor > 0) add_monitor_notes(args, plan, setup);
  if (setup.options.approach.enabled()) add_vias(args, setup, records, plan);
  VRREG_THROW_UNLESS(args.monitor_program.empty() || args.monitor > 0,
                     "--monitor-program needs --monitor");
  // Every output is made before any is written, then all are written or none.
  std::vector<io::OutputFile> outputs;
  if (!args.export_format.empty()) outputs.push_back({args.program, plan_program(args, plan)});
  if (!args.monitor_program.empty())
    outputs.push_back({args.monitor_program, plan_program(args, plan, true)});
  if (!args.output.empty()) {
    outputs.push_back(
        {args.output, io::format_plan_csv(plan_rows(plan), plan_comments(args, setup, plan))});
  }
  io::write_files_atomically(outputs);
  if (args.json) {
    print_json(plan_json(args, setup, plan));
  } else {
    print_plan_summary(args, setup, plan);
  }
}

void run_plan(const PlanArgs& args) {
  try {
    run_plan_unchecked(args);
  } catch (const io::FileError&) {
    throw;  // already names file and line
  } catch (const InputError& e) {
    const std::string what = e.what();
    throw InputError(what.starts_with("plan: ") ? what : "plan: " + what);
  }
}

void add_plan_command(CLI::App& app) {
  auto args = std::make_shared<PlanArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plan",
      "Procedure 1 (paper section 6): where to measure fiducials around M part points, "
      "with joints and a visiting order, as a plan CSV");
  add_input_option(*cmd, "--parts", args->parts,
                   "CSV of part points: point,robot_x_mm,robot_y_mm,robot_z_mm (robot base frame), "
                   "or a measurement CSV whose target rows are the part points")
      ->required();
  cmd->add_option("--halfwidth-mm", args->halfwidth_mm,
                  "placement tolerance S in mm: each part point may land within +-S (rounded up "
                  "so the part point sits at a grid cell's centre)")
      ->required()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--spacing-mm", args->spacing_mm, "grid spacing A in mm")
      ->required()
      ->check(CLI::PositiveNumber);
  add_robot_option(*cmd, "--robot", args->robot,
                   "ur5, lwr4 (defaults from the simulated test bed), ur3, ur10, ur5e, or a robot "
                   "file (URDF, or JSON/YAML)")
      ->required();
  args->links.add_to(*cmd, "--robot");
  cmd->add_option("--sigma-noise-mm", args->sigma_noise_mm,
                  "noise sigma_noise in mm for d_min > 2.5 sigma_noise (Eq. 9); default the "
                  "paper's: 0.114 (Table 1, UR5), 0.077 for lwr4 (section 5.2)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--force", args->force, "write the plan even when d_min <= 2.5 sigma_noise");
  cmd->add_option("--tool-mm", args->tool_mm,
                  "TCP (tracked sphere) offset X Y Z in the flange "
                  "frame, mm")
      ->expected(3);
  cmd->add_option("--rpy-deg", args->rpy_deg,
                  "fixed TCP orientation ROLL PITCH YAW in deg, R = Rz(yaw) Ry(pitch) Rx(roll)")
      ->expected(3);
  cmd->add_option("--psi-deg", args->psi_deg, "LWR arm angle psi in deg for every location");
  cmd->add_option("--home-deg", args->home_deg,
                  "joints Q1 ... QN in deg: each part point takes the IK solution nearest these")
      ->expected(1, kinematics::kMaxJoints);
  not_a_file(*cmd, cmd->add_option("--norm", args->norm,
                                   "joint-space distance for 'nearest': l2 (paper) or linf")
                       ->check(CLI::IsMember({"l2", "linf"})));
  cmd->add_option("--offset-tilt-deg", args->offset_tilt_deg,
                  "add poses with the tool tilted by this angle about its x and y axes (+-) at the "
                  "corners and centre of the volume, so that the marker's offset on the flange is "
                  "observable: register with --estimate-marker-offset (docs/hand-eye.md); 15-25 "
                  "is typical")
      ->check(CLI::Range(0.1, 60.0));
  cmd->add_option("--monitor", args->monitor,
                  "add N monitor points (fiducial locations spread over the volume, role "
                  "monitor) that vrreg check reads again later (docs/monitoring.md); without N, "
                  "4 off one plane (3 lie on a plane and miss a change along its normal)")
      ->expected(0, 1)
      ->default_str(std::to_string(planning::kDefaultMonitorPoints))
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--monitor-visits", args->monitor_visits,
                  "visits of each monitor point in the programs (the robot's repeatability "
                  "averages over visits)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  not_a_file(*cmd, cmd->add_option("--approach-from", args->approach_from,
                                   "make every joint arrive at every location from one side "
                                   "(against lost motion): + or - for all joints, or one per "
                                   "joint (+,+,-,+,+,+); a via point before each location, "
                                   "--approach-offset-deg away in joint space (docs/"
                                   "joint-space-model.md, Lost motion)"));
  cmd->add_option("--approach-offset-deg", args->approach_offset_deg,
                  "with --approach-from: the via points' offset per joint in deg")
      ->capture_default_str()
      ->needs("--approach-from")
      ->check(CLI::Range(0.01, 30.0));
  add_program_options(*cmd, *args);
  add_output_option(*cmd, "-o,--output", args->output, "write the plan CSV here");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the summary");
  cmd->callback([args] { run_plan(*args); });
}

}  // namespace

PlanSetup make_plan_setup(const PlanArgs& args) { return make_setup(args); }

VRREG_REGISTER_COMMAND(50, add_plan_command);

}  // namespace vrreg::cli
