// SPDX-License-Identifier: Apache-2.0
// vrreg fk: forward kinematics of a robot (built-in or robot file) at given joint values:
// the flange / TCP pose, its configuration label and, for the LWR 4+, the arm angle psi.
#include <cstdio>
#include <memory>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "robot_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"

namespace vrreg::cli {
namespace {

struct FkArgs {
  std::string robot;
  std::vector<double> joints;
  bool degrees = false;
  std::vector<double> tool_mm;
  RobotLinkFlags links;
  bool json = false;
};

void run_fk(const FkArgs& args) {
  const kinematics::SerialChain chain =
      robot_from_args(args.robot, args.tool_mm, args.links.links());
  check_finite(args.joints, "joint values");
  VRREG_THROW_UNLESS(static_cast<int>(args.joints.size()) == chain.n_joints(),
                     "robot '" << chain.name() << "' has " << chain.n_joints() << " joints, got "
                               << args.joints.size() << " joint values");
  kinematics::JointVector q(chain.n_joints());
  for (int i = 0; i < chain.n_joints(); ++i) {
    const double v = args.joints[static_cast<std::size_t>(i)];
    // --deg: revolute joints in deg, prismatic ones in mm (without it: rad and m).
    if (!args.degrees) {
      q(i) = v;
    } else {
      q(i) = chain.prismatic(i) ? units::mm_to_m(v) : units::deg_to_rad(v);
    }
  }
  const Eigen::Isometry3d pose = kinematics::forward_kinematics(chain, q);
  const std::optional<kinematics::ConfigurationLabel> config =
      kinematics::configuration_of(chain, q);
  std::optional<kinematics::LwrArmState> arm;
  if (chain.family() == kinematics::ChainFamily::kLwr) arm = kinematics::lwr_arm_state(chain, q);
  const bool in_limits = chain.within_limits(q);

  if (args.json) {
    nlohmann::json j;
    j["robot"] = chain.name();
    j["frame"] = pose_frame_description(chain);
    j["q_rad"] = std::vector<double>(q.data(), q.data() + q.size());
    j["q_deg"] = shown_joints_json(chain, q);
    if (chain.coupled()) j["joint_names"] = joint_names_json(chain);
    pose_to_json(pose, j);
    if (config) {
      j["config"] = config->to_string();
      j["config_index"] = config->index();
    }
    if (arm) {
      j["psi_deg"] = units::rad_to_deg(arm->psi_rad);
      j["singular"] = singular_json(arm->singular);
    }
    j["within_limits"] = in_limits;
    print_json(j);
    return;
  }
  std::printf("%s forward kinematics: %s\n", chain.name().c_str(),
              pose_frame_description(chain).c_str());
  std::printf("  joints [deg]     ");
  for (int i = 0; i < q.size(); ++i) std::printf(" %.6f", shown_joint_value(chain, i, q(i)));
  std::printf("%s", prismatic_note(chain).c_str());
  std::printf("%s\n", in_limits ? "" : "   (outside the joint limits)");
  if (chain.coupled()) std::printf("  joint variables   %s\n", coupled_joints_text(chain).c_str());
  const std::string xyz = xyz_mm_text(pose.translation());
  const std::string rpy = rpy_deg_text(pose.linear());
  std::printf("  position [mm]     %s\n", xyz.c_str());
  std::printf("  rpy [deg]         %s   (roll pitch yaw, R = Rz(yaw) Ry(pitch) Rx(roll))\n",
              rpy.c_str());
  for (int r = 0; r < 3; ++r) {
    std::printf("  %s   %12.9f %12.9f %12.9f\n", r == 0 ? "rotation       " : "               ",
                pose.linear()(r, 0), pose.linear()(r, 1), pose.linear()(r, 2));
  }
  if (config)
    std::printf("  configuration     %s (index %d)\n", config->to_string().c_str(),
                config->index());
  if (arm) {
    std::printf("  arm angle psi     %.6f deg\n", units::rad_to_deg(arm->psi_rad));
    if (arm->singular != kinematics::kNoSingularity) {
      std::printf("  singular          %s\n", kinematics::singularity_names(arm->singular).c_str());
    }
  }
  // The pose to the picometre and 1e-12 deg, so that the command inverts it even where the IK is
  // ill-conditioned: at a singular wrist, the last printed digit would move the free angle.
  std::printf("  back to joints:   vrreg ik %s --xyz-mm %s --rpy-deg %s", args.robot.c_str(),
              xyz_mm_text(pose.translation(), 9).c_str(), rpy_deg_text(pose.linear(), 12).c_str());
  if (arm) std::printf(" --psi-deg %.6f", units::rad_to_deg(arm->psi_rad));
  if (!args.tool_mm.empty()) {
    std::printf(" --tool-mm %g %g %g", args.tool_mm[0], args.tool_mm[1], args.tool_mm[2]);
  }
  if (!args.links.tip_link.empty()) std::printf(" --tip-link %s", args.links.tip_link.c_str());
  if (!args.links.base_link.empty()) std::printf(" --base-link %s", args.links.base_link.c_str());
  std::printf("\n");
}

void add_fk_command(CLI::App& app) {
  auto args = std::make_shared<FkArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fk", "forward kinematics: the flange (or TCP) pose of a robot at given joint values");
  add_robot_option(*cmd, "robot", args->robot,
                   "ur3, ur5, ur10, ur5e, lwr4, or a robot file (URDF, or JSON/YAML: a DH table "
                   "or a URDF with its base and tip link)")
      ->required();
  cmd->add_option("joints", args->joints,
                  "joint values Q1 ... QN (rad, or deg with --deg; a prismatic joint's in m, or mm "
                  "with --deg)")
      ->required();
  cmd->add_flag("--deg", args->degrees, "joint values are in degrees (prismatic joints: mm)");
  cmd->add_option("--tool-mm", args->tool_mm,
                  "TCP offset X Y Z in the flange frame, mm (replaces the robot's tool)")
      ->expected(3);
  args->links.add_to(*cmd, "ROBOT");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args] { run_fk(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(60, add_fk_command);

}  // namespace vrreg::cli
