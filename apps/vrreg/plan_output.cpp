// SPDX-License-Identifier: Apache-2.0
#include "plan_output.hpp"

#include <cstdio>
#include <map>

#include "cli_support.hpp"
#include "robot_cli.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/result_json.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/planning/approach.hpp"
#include "vrreg/planning/robot_program.hpp"

namespace vrreg::cli {
namespace {

std::string fixed(double value, int decimals) { return format_fixed(value, decimals); }

std::string degrees_list(const Eigen::Ref<const Eigen::VectorXd>& q_rad) {
  std::string out;
  for (Eigen::Index i = 0; i < q_rad.size(); ++i) {
    out += (i > 0 ? " " : "") + fixed(units::rad_to_deg(q_rad(i)), 3);
  }
  return out;
}

std::string sigma_source(const PlanArgs& args) {
  return args.sigma_noise_mm ? "given" : "the paper's; give --sigma-noise-mm for your cell";
}

std::string visit_order(const planning::PlanResult& plan) {
  std::vector<std::string> names(plan.parts.size());
  for (const planning::PartPlan& p : plan.parts) {
    names[static_cast<std::size_t>(p.visit_rank)] = p.name;
  }
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) out += (k > 0 ? " -> " : "") + names[k];
  return out;
}

std::map<int, std::string> config_labels(const planning::PlanResult& plan) {
  std::map<int, std::string> labels;
  for (const planning::PlannedLocation& l : plan.locations) {
    labels.emplace(l.config.index(), l.config.to_string());
  }
  return labels;
}

// "+ + - + + +": each joint's approach direction.
std::string approach_text(const planning::ApproachOptions& approach) {
  std::string out;
  for (Eigen::Index j = 0; j < approach.direction.size(); ++j) {
    out += (j > 0 ? " " : "") + std::string(approach.direction(j) > 0 ? "+" : "-");
  }
  return out;
}

planning::ApproachCost approach_cost(const PlanArgs& args, const planning::PlanResult& plan) {
  planning::ProgramOptions program;
  if (args.repeats > 0) program.repeats = args.repeats;
  return planning::approach_cost(plan, program);
}

// One line: the approach directions and what the via points cost.
std::string approach_line(const PlanArgs& args, const PlanSetup& setup,
                          const planning::PlanResult& plan) {
  const planning::ApproachOptions& a = setup.options.approach;
  const planning::ApproachCost c = approach_cost(args, plan);
  const planning::ProgramOptions program;
  return "every joint arrives from " + approach_text(a) + " (joints 1.." +
         std::to_string(a.direction.size()) + "): a via point " +
         fixed(units::rad_to_deg(a.offset_rad), 3) + " deg before each of " +
         std::to_string(c.n_via) + " locations; joint path (farthest joint per move) " +
         fixed(units::rad_to_deg(c.joint_path_rad), 1) + " -> " +
         fixed(units::rad_to_deg(c.joint_path_with_vias_rad), 1) + " deg, movej time " +
         fixed(c.motion_s, 1) + " -> " + fixed(c.motion_with_vias_s, 1) + " s (+" +
         fixed(c.motion_with_vias_s - c.motion_s, 1) + " s at v " +
         fixed(program.joint_speed_rad_s, 2) + " rad/s, a " + fixed(program.joint_accel_rad_s2, 2) +
         " rad/s^2)";
}

std::string psi_text(const PlanSetup& setup) {
  return setup.chain.family() == kinematics::ChainFamily::kLwr
             ? fixed(units::rad_to_deg(setup.options.arm.psi_rad), 3)
             : "n/a";
}

}  // namespace

std::vector<io::PlanRow> plan_rows(const planning::PlanResult& plan) {
  std::vector<io::PlanRow> rows;
  rows.reserve(plan.locations.size());
  for (const planning::PlannedLocation& l : plan.locations) {
    io::PlanRow& r = rows.emplace_back();
    r.point = l.point;
    r.role = l.role;
    r.part = plan.parts[static_cast<std::size_t>(l.part)].name;
    r.robot_m = l.robot_m;
    r.config = l.config.index();
    r.q_rad.assign(l.q_rad.data(), l.q_rad.data() + l.q_rad.size());
    if (l.via_q_rad) {
      r.via = io::PlanVia{l.via_robot_m, {l.via_q_rad->data(),
                                          l.via_q_rad->data() + l.via_q_rad->size()}};
    }
  }
  return rows;
}

std::vector<std::string> plan_comments(const PlanArgs& args, const PlanSetup& setup,
                                       const planning::PlanResult& plan) {
  const planning::PlanOptions& o = setup.options;
  const planning::CubeGeometry& c = plan.cube;
  std::vector<std::string> out{
      "vrreg plan: Procedure 1 (paper section 6, Fig. 16), where to measure",
      "parts: " + args.parts + " (" + std::to_string(plan.parts.size()) + " part points)",
      "robot: " + setup.chain.name(),
      "tool_mm: " + xyz_mm_text(setup.chain.T_flange_tcp().translation(), 3) +
          " (TCP = tracked point, flange frame)",
      "tool_rpy_deg: " + rpy_deg_text(o.arm.R_base_tcp, 3) +
          " (fixed TCP orientation in the robot base frame, R = Rz(yaw) Ry(pitch) Rx(roll))",
      "psi_deg: " + psi_text(setup),
      "halfwidth_mm: " + format_mm(c.requested_halfwidth_m) + " requested, " +
          format_mm(c.halfwidth_m) + " covered (part point at the centre of a grid cell)",
      "spacing_mm: " + format_mm(c.spacing_m),
      "nodes_per_axis: " + std::to_string(c.nodes_per_axis) + " (" + std::to_string(c.n_nodes()) +
          " fiducials per part point)",
      "d_min_mm: " + format_mm(c.d_min_m()) + " (sqrt(3)/2 A, target to its 8 nearest fiducials)",
      "d_max_mm: " + format_mm(c.d_max_m()),
      "sigma_noise_mm: " + format_mm(o.sigma_noise_m) + " (" + sigma_source(args) + ")",
      "eq9: d_min > 2.5 sigma_noise = " + format_mm(plan.dmin.threshold_m) +
          " mm: " + (plan.dmin.ok ? "ok" : "FAILED, forced"),
      std::string("joints: IK solution nearest the part point's joints, norm ") +
          kinematics::to_string(o.arm.norm) +
          (o.arm.home_q_rad ? "; part points nearest home_deg " + degrees_list(*o.arm.home_q_rad)
                            : "; part points in the first configuration the IK lists"),
  };
  for (const auto& [index, label] : config_labels(plan)) {
    out.push_back("config " + std::to_string(index) + ": " + label);
  }
  out.push_back("order: cubes " + visit_order(plan) +
                "; serpentine inside each cube (consecutive fiducials one grid step apart), the "
                "target between two corners of its cell");
  out.push_back("travel_mm: inside cubes " + format_mm(plan.within_cubes_m, 1) +
                ", between cubes " + format_mm(plan.between_cubes_m, 1) +
                " (input order: " + format_mm(plan.naive_between_cubes_m, 1) + ")");
  if (o.approach.enabled()) {
    out.push_back("approach: " + approach_line(args, setup, plan));
    out.push_back(
        "via rows: moved to just before the next row (same point), never measured; drop them "
        "to make a measurement CSV");
  }
  out.push_back(
      "rows: visiting order; add sensor_x_mm,sensor_y_mm,sensor_z_mm (and drop part) "
      "to make a measurement CSV");
  return out;
}

nlohmann::json plan_json(const PlanArgs& args, const PlanSetup& setup,
                         const planning::PlanResult& plan) {
  const planning::PlanOptions& o = setup.options;
  const planning::CubeGeometry& c = plan.cube;
  nlohmann::json j;
  j["parts_file"] = args.parts;
  j["robot"] = setup.chain.name();
  j["tool_mm"] = io::json_mm3(setup.chain.T_flange_tcp().translation());
  const Eigen::Vector3d rpy = kinematics::rpy_from_rotation(o.arm.R_base_tcp);
  j["tool_rpy_deg"] = {units::rad_to_deg(rpy(0)), units::rad_to_deg(rpy(1)),
                       units::rad_to_deg(rpy(2))};
  if (setup.chain.family() == kinematics::ChainFamily::kLwr) {
    j["psi_deg"] = units::rad_to_deg(o.arm.psi_rad);
  }
  j["norm"] = kinematics::to_string(o.arm.norm);
  j["halfwidth_mm"] = units::m_to_mm(c.requested_halfwidth_m);
  j["covered_halfwidth_mm"] = units::m_to_mm(c.halfwidth_m);
  j["spacing_mm"] = units::m_to_mm(c.spacing_m);
  j["nodes_per_axis"] = c.nodes_per_axis;
  j["n_fiducials_per_part"] = c.n_nodes();
  j["n_locations"] = plan.locations.size();
  j["d_min_mm"] = units::m_to_mm(c.d_min_m());
  j["d_max_mm"] = units::m_to_mm(c.d_max_m());
  j["sigma_noise_mm"] = units::m_to_mm(o.sigma_noise_m);
  j["sigma_noise_default"] = !args.sigma_noise_mm.has_value();
  j["dmin_threshold_mm"] = units::m_to_mm(plan.dmin.threshold_m);
  j["dmin_ok"] = plan.dmin.ok;
  j["forced"] = plan.dmin.forced;
  nlohmann::json parts = nlohmann::json::array();
  for (const planning::PartPlan& p : plan.parts) {
    parts.push_back({{"point", p.name},
                     {"robot_mm", io::json_mm3(p.robot_m)},
                     {"config", p.config.index()},
                     {"config_label", p.config.to_string()},
                     {"q_deg", degrees_json(p.q_rad)},
                     {"n_fiducials", p.n_fiducials},
                     {"d_min_mm", units::m_to_mm(p.d_min_m)},
                     {"d_max_mm", units::m_to_mm(p.d_max_m)},
                     {"n_other_config", p.n_other_config},
                     {"max_joint_distance_deg", units::rad_to_deg(p.max_joint_distance_rad)},
                     {"visit_rank", p.visit_rank}});
  }
  j["parts"] = parts;
  nlohmann::json order = nlohmann::json::array();
  std::vector<std::string> names(plan.parts.size());
  for (const planning::PartPlan& p : plan.parts)
    names[static_cast<std::size_t>(p.visit_rank)] = p.name;
  for (const std::string& n : names) order.push_back(n);
  j["visit_order"] = order;
  j["within_cubes_mm"] = units::m_to_mm(plan.within_cubes_m);
  j["between_cubes_mm"] = units::m_to_mm(plan.between_cubes_m);
  j["input_order_between_cubes_mm"] = units::m_to_mm(plan.naive_between_cubes_m);
  nlohmann::json overlaps = nlohmann::json::array();
  for (const auto& [a, b] : plan.overlapping) {
    overlaps.push_back({plan.parts[static_cast<std::size_t>(a)].name,
                        plan.parts[static_cast<std::size_t>(b)].name});
  }
  j["overlapping"] = overlaps;
  if (o.approach.enabled()) {
    const planning::ApproachCost cost = approach_cost(args, plan);
    const planning::ProgramOptions program;
    nlohmann::json signs = nlohmann::json::array();
    for (Eigen::Index k = 0; k < o.approach.direction.size(); ++k) {
      signs.push_back(static_cast<int>(o.approach.direction(k)));
    }
    j["approach"] = {{"direction", signs},
                     {"offset_deg", units::rad_to_deg(o.approach.offset_rad)},
                     {"n_via", cost.n_via},
                     {"joint_path_deg", units::rad_to_deg(cost.joint_path_rad)},
                     {"joint_path_with_vias_deg", units::rad_to_deg(cost.joint_path_with_vias_rad)},
                     {"motion_s", cost.motion_s},
                     {"motion_with_vias_s", cost.motion_with_vias_s},
                     {"joint_speed_rad_s", program.joint_speed_rad_s},
                     {"joint_accel_rad_s2", program.joint_accel_rad_s2}};
  }
  j["notes"] = setup.notes;
  j["output"] = args.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(args.output);
  return j;
}

void print_plan_summary(const PlanArgs& args, const PlanSetup& setup,
                        const planning::PlanResult& plan) {
  const planning::PlanOptions& o = setup.options;
  const planning::CubeGeometry& c = plan.cube;
  const int n = c.nodes_per_axis;
  std::printf("plan for %zu part points from %s on %s (lengths in mm)\n", plan.parts.size(),
              args.parts.c_str(), setup.chain.name().c_str());
  std::printf("  tracked point         %s\n", pose_frame_description(setup.chain).c_str());
  std::printf("  tool orientation      rpy %s deg (fixed, robot base frame)",
              rpy_deg_text(o.arm.R_base_tcp, 1).c_str());
  if (setup.chain.family() == kinematics::ChainFamily::kLwr)
    std::printf(", psi %s deg", psi_text(setup).c_str());
  std::printf("\n");
  std::printf(
      "  placement tolerance   S = %s mm asked, %s mm covered (%d cells of A per axis: the "
      "part point at a cell centre)\n",
      format_mm(c.requested_halfwidth_m).c_str(), format_mm(c.halfwidth_m).c_str(), n - 1);
  std::printf("  grid spacing          A = %s mm: %d x %d x %d = %lld fiducials per part point\n",
              format_mm(c.spacing_m).c_str(), n, n, n, c.n_nodes());
  std::printf("  target-fiducial d     d_min = %s mm (8 nearest, sqrt(3)/2 A), d_max = %s mm\n",
              format_mm(c.d_min_m()).c_str(), format_mm(c.d_max_m()).c_str());
  std::printf(
      "  Eq. 9                 d_min %s 2.5 sigma_noise = %s mm: %s (sigma_noise = %s mm, %s)\n",
      plan.dmin.ok ? ">" : "<=", format_mm(plan.dmin.threshold_m).c_str(),
      plan.dmin.ok ? "ok" : "FAILED (forced)", format_mm(o.sigma_noise_m).c_str(),
      sigma_source(args).c_str());
  std::printf(
      "  joints                each fiducial: the IK solution nearest its part point's "
      "joints (%s)\n",
      o.arm.norm == kinematics::JointNorm::kL2 ? "L2" : "Linf");
  std::printf("  %-12s %10s %10s %10s  %-40s %9s %12s %11s %5s\n", "part", "x", "y", "z",
              "configuration (index label)", "fiducials", "other config", "max dq deg", "visit");
  for (const planning::PartPlan& p : plan.parts) {
    std::printf("  %-12s %10s %10s %10s  %-40s %9lld %12lld %11.3f %5d\n", p.name.c_str(),
                format_mm(p.robot_m.x()).c_str(), format_mm(p.robot_m.y()).c_str(),
                format_mm(p.robot_m.z()).c_str(),
                (std::to_string(p.config.index()) + " " + p.config.to_string()).c_str(),
                p.n_fiducials, p.n_other_config, units::rad_to_deg(p.max_joint_distance_rad),
                p.visit_rank + 1);
  }
  std::printf("  visiting order        %s: %zu locations (%lld fiducials, %zu target%s)\n",
              visit_order(plan).c_str(), plan.locations.size(),
              static_cast<long long>(plan.parts.size()) * c.n_nodes(), plan.parts.size(),
              plan.parts.size() == 1 ? "" : "s");
  std::printf(
      "  travel                %s mm inside cubes, %s mm between cubes (input order: %s mm)\n",
      format_mm(plan.within_cubes_m, 1).c_str(), format_mm(plan.between_cubes_m, 1).c_str(),
      format_mm(plan.naive_between_cubes_m, 1).c_str());
  if (o.approach.enabled()) {
    std::printf("  approach              %s\n", approach_line(args, setup, plan).c_str());
  }
  for (const auto& [a, b] : plan.overlapping) {
    std::printf("  note: the cubes of %s and %s overlap or touch\n",
                plan.parts[static_cast<std::size_t>(a)].name.c_str(),
                plan.parts[static_cast<std::size_t>(b)].name.c_str());
  }
  for (const std::string& note : setup.notes)
    std::printf("  default               %s\n", note.c_str());
  if (args.output.empty()) {
    std::printf("  no plan written (give -o FILE)\n");
  } else {
    std::printf("  plan written to %s\n", args.output.c_str());
  }
}

}  // namespace vrreg::cli
