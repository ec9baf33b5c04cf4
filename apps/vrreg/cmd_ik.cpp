// SPDX-License-Identifier: Apache-2.0
// vrreg ik: every inverse-kinematics solution of a flange (or TCP) pose, each labelled with its
// configuration (closed form for UR and LWR 4+ chains, at an arm angle psi with the feasible psi
// ranges for the LWR; numerical for any other chain). No solution: the answer, then exit 3.
#include <cstdio>
#include <memory>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "robot_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/lwr_psi_intervals.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/ur_ik.hpp"

namespace vrreg::cli {
namespace {

using kinematics::ChainFamily;
using kinematics::IkResult;

struct IkArgs {
  std::string robot;
  std::vector<double> xyz_mm;
  std::vector<double> rpy_deg;
  std::vector<double> rotation;
  std::optional<double> psi_deg;
  std::vector<double> tool_mm;
  std::vector<double> current_deg;
  RobotLinkFlags links;
  bool json = false;
};

Eigen::Isometry3d target_pose(const IkArgs& args) {
  check_finite(args.xyz_mm, "--xyz-mm");
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() << units::mm_to_m(args.xyz_mm[0]), units::mm_to_m(args.xyz_mm[1]),
      units::mm_to_m(args.xyz_mm[2]);
  VRREG_THROW_UNLESS(args.rpy_deg.empty() != args.rotation.empty(),
                     "give the orientation with either --rpy-deg ROLL PITCH YAW or --rotation "
                     "R00 R01 R02 R10 R11 R12 R20 R21 R22");
  if (!args.rpy_deg.empty()) {
    check_finite(args.rpy_deg, "--rpy-deg");
    t.linear() = kinematics::rotation_from_rpy(units::deg_to_rad(args.rpy_deg[0]),
                                               units::deg_to_rad(args.rpy_deg[1]),
                                               units::deg_to_rad(args.rpy_deg[2]));
  } else {
    check_finite(args.rotation, "--rotation");
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        t.linear()(r, c) = args.rotation[static_cast<std::size_t>(3 * r + c)];
    }
    kinematics::check_pose(t, "--rotation");
  }
  return t;
}

std::string degrees_text(double rad) { return format_fixed(units::rad_to_deg(rad), 6); }

void print_human(const IkArgs& args, const kinematics::SerialChain& chain,
                 const Eigen::Isometry3d& t, const IkResult& r,
                 const std::optional<double>& psi_rad,
                 const std::optional<kinematics::PsiIntervalsResult>& psi_ranges) {
  std::printf("%s inverse kinematics: %s\n", chain.name().c_str(),
              pose_frame_description(chain).c_str());
  std::printf("  target            xyz = %s mm, rpy = %s deg",
              xyz_mm_text(t.translation(), 3).c_str(), rpy_deg_text(t.linear(), 3).c_str());
  if (psi_rad) {
    std::printf(", psi = %s deg", degrees_text(*psi_rad).c_str());
  } else if (chain.family() == ChainFamily::kLwr) {
    std::printf(", psi free (per configuration: 0, or the feasible arm angle nearest 0)");
  }
  std::printf("\n");
  if (!r.ok()) {
    std::printf("  no solution (%s): %s\n", kinematics::to_string(r.status), r.message.c_str());
  } else {
    std::printf("  %zu solution%s%s; joint values in deg%s:\n", r.solutions.size(),
                r.solutions.size() == 1 ? "" : "s",
                args.current_deg.empty() ? "" : " (nearest the current joints)",
                prismatic_note(chain).c_str());
    std::printf("  #  %-40s", "configuration");
    for (int i = 0; i < chain.n_joints(); ++i)
      std::printf(" %11s", ("q" + std::to_string(i + 1)).c_str());
    std::printf("\n");
    for (const kinematics::IkSolution& s : r.solutions) {
      std::printf("  %d  %-40s", s.config.index(), s.config.to_string().c_str());
      for (int i = 0; i < s.q_rad.size(); ++i)
        std::printf(" %11.6f", shown_joint_value(chain, static_cast<int>(i), s.q_rad(i)));
      if (s.psi_rad)
        std::printf("  psi %s deg", format_fixed(units::rad_to_deg(*s.psi_rad), 3).c_str());
      if (s.singular != kinematics::kNoSingularity) {
        std::printf("  singular: %s", kinematics::singularity_names(s.singular).c_str());
      }
      std::printf("\n");
    }
  }
  if (r.n_outside_limits > 0) {
    std::printf("  %d more solution%s outside the joint limits\n", r.n_outside_limits,
                r.n_outside_limits == 1 ? "" : "s");
  }
  if (psi_ranges && psi_ranges->ok()) {
    std::printf("  feasible psi within the joint limits [deg]:\n");
    for (int c = 0; c < 8; ++c) {
      const auto& list = psi_ranges->intervals[static_cast<std::size_t>(c)];
      std::printf("    %s  ",
                  kinematics::ConfigurationLabel(kinematics::ArmKind::kLwr, c).to_string().c_str());
      if (list.empty()) std::printf(" none");
      for (const kinematics::PsiInterval& i : list) {
        std::printf(" [%.2f, %.2f]", units::rad_to_deg(i.lower_rad),
                    units::rad_to_deg(i.upper_rad));
      }
      std::printf("\n");
    }
  }
}

nlohmann::json ik_json(const kinematics::SerialChain& chain, const Eigen::Isometry3d& t,
                       const IkResult& r, const std::optional<double>& psi_rad,
                       const std::optional<kinematics::PsiIntervalsResult>& psi_ranges);

void run_ik(const IkArgs& args) {
  const kinematics::SerialChain chain =
      robot_from_args(args.robot, args.tool_mm, args.links.links());
  const Eigen::Isometry3d t = target_pose(args);
  std::optional<double> psi_rad;
  if (args.psi_deg) {
    VRREG_THROW_UNLESS(std::isfinite(*args.psi_deg), "--psi-deg is not a finite number");
    VRREG_THROW_UNLESS(
        chain.family() == ChainFamily::kLwr,
        "--psi-deg applies to 7-joint arms (lwr4); robot '" << chain.name() << "' has none");
    psi_rad = units::deg_to_rad(*args.psi_deg);
  }
  IkResult r;
  if (args.current_deg.empty()) {
    r = kinematics::inverse_kinematics(chain, t, psi_rad);
  } else {
    check_finite(args.current_deg, "--current-deg");
    VRREG_THROW_UNLESS(static_cast<int>(args.current_deg.size()) == chain.n_joints(),
                       "--current-deg: robot '" << chain.name() << "' has " << chain.n_joints()
                                                << " joints, got " << args.current_deg.size());
    // In the units the joints are shown in: deg, mm for a prismatic joint.
    Eigen::VectorXd current(chain.n_joints());
    for (int i = 0; i < chain.n_joints(); ++i) {
      const double shown = args.current_deg[static_cast<std::size_t>(i)];
      current(i) = chain.prismatic(i) ? units::mm_to_m(shown) : units::deg_to_rad(shown);
    }
    r = kinematics::inverse_kinematics_nearest(chain, t, current, psi_rad);
  }
  std::optional<kinematics::PsiIntervalsResult> psi_ranges;
  if (chain.family() == ChainFamily::kLwr) psi_ranges = kinematics::lwr_feasible_psi(chain, t);

  if (!args.json) {
    print_human(args, chain, t, r, psi_rad, psi_ranges);
  } else {
    print_json(ik_json(chain, t, r, psi_rad, psi_ranges));
  }
  if (!r.ok()) {
    std::fflush(stdout);
    throw NoSolution("ik: no solution (" + std::string(kinematics::to_string(r.status)) +
                     "): " + r.message);
  }
}

nlohmann::json ik_json(const kinematics::SerialChain& chain, const Eigen::Isometry3d& t,
                       const IkResult& r, const std::optional<double>& psi_rad,
                       const std::optional<kinematics::PsiIntervalsResult>& psi_ranges) {
  nlohmann::json j;
  j["robot"] = chain.name();
  j["frame"] = pose_frame_description(chain);
  nlohmann::json target;
  pose_to_json(t, target);
  j["target"] = target;
  if (psi_rad) j["psi_deg"] = units::rad_to_deg(*psi_rad);
  j["status"] = kinematics::to_string(r.status);
  j["message"] = r.message;
  j["n_outside_limits"] = r.n_outside_limits;
  j["singular"] = singular_json(r.singular);
  nlohmann::json solutions = nlohmann::json::array();
  for (const kinematics::IkSolution& s : r.solutions) {
    solutions.push_back(
        {{"q_rad", std::vector<double>(s.q_rad.data(), s.q_rad.data() + s.q_rad.size())},
         {"q_deg", shown_joints_json(chain, s.q_rad)},
         {"config", s.config.to_string()},
         {"config_index", s.config.index()},
         {"singular", singular_json(s.singular)}});
    if (s.psi_rad) solutions.back()["psi_deg"] = units::rad_to_deg(*s.psi_rad);
  }
  j["solutions"] = solutions;
  if (psi_ranges && psi_ranges->ok()) {
    nlohmann::json ranges = nlohmann::json::object();
    for (int c = 0; c < 8; ++c) {
      nlohmann::json list = nlohmann::json::array();
      for (const kinematics::PsiInterval& i : psi_ranges->intervals[static_cast<std::size_t>(c)]) {
        list.push_back({units::rad_to_deg(i.lower_rad), units::rad_to_deg(i.upper_rad)});
      }
      ranges[kinematics::ConfigurationLabel(kinematics::ArmKind::kLwr, c).to_string()] = list;
    }
    j["feasible_psi_deg"] = ranges;
  }
  return j;
}

void add_ik_command(CLI::App& app) {
  auto args = std::make_shared<IkArgs>();
  CLI::App* cmd = app.add_subcommand(
      "ik",
      "inverse kinematics: every joint solution of a flange (or TCP) pose, labelled by "
      "arm configuration (UR: up to 8; LWR 4+: up to 8 per arm angle psi; any other chain: "
      "numerically, one per configuration class found); exit status 3 when there is none");
  add_robot_option(*cmd, "robot", args->robot,
                   "ur3, ur5, ur10, ur5e, lwr4, or a robot file (URDF, or JSON/YAML: a DH table "
                   "or a URDF with its base and tip link)")
      ->required();
  cmd->add_option("--xyz-mm", args->xyz_mm, "position X Y Z in mm")->expected(3)->required();
  cmd->add_option("--rpy-deg", args->rpy_deg,
                  "orientation ROLL PITCH YAW in deg, R = Rz(yaw) Ry(pitch) Rx(roll)")
      ->expected(3);
  cmd->add_option("--rotation", args->rotation,
                  "orientation as a rotation matrix, 9 numbers row by row")
      ->expected(9);
  cmd->add_option(
      "--psi-deg", args->psi_deg,
      "arm angle psi in deg (7-joint arms; default: free, each configuration at 0 or at the "
      "feasible arm angle nearest 0 within the joint limits)");
  cmd->add_option("--tool-mm", args->tool_mm,
                  "TCP offset X Y Z in the flange frame, mm (replaces the robot's tool)")
      ->expected(3);
  cmd->add_option("--current-deg", args->current_deg,
                  "current joints Q1 ... QN in deg (mm for a prismatic joint): print only the "
                  "solution a controller picks (nearest, 2 pi shifts included; a numerical IK "
                  "starts from them)")
      ->expected(1, kinematics::kMaxJoints);
  args->links.add_to(*cmd, "ROBOT");
  cmd->add_flag("--json", args->json,
                "print one JSON object {\"solutions\": [{\"q_rad\", \"config\", ...}], ...}");
  cmd->callback([args] { run_ik(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(61, add_ik_command);

}  // namespace vrreg::cli
