// SPDX-License-Identifier: Apache-2.0
#include "robot_cli.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>

#include "file_options.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/robot_io/robot_file.hpp"

namespace vrreg::cli {

void check_finite(const std::vector<double>& values, const char* what) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    VRREG_THROW_UNLESS(std::isfinite(values[i]), what << ": value " << i + 1
                                                      << " is not a finite number (" << values[i]
                                                      << ")");
  }
}

void RobotLinkFlags::add_to(CLI::App& command, const std::string& robot_option) {
  not_a_file(command, command.add_option("--tip-link", tip_link,
                                         "with a URDF robot (" + robot_option +
                                             "): the link the TCP is on (needed when several "
                                             "leaves are equally deep)"));
  not_a_file(command, command.add_option("--base-link", base_link,
                                         "with a URDF robot (" + robot_option +
                                             "): the link whose frame poses are in (default the "
                                             "root)"));
}

io::UrdfChainOptions RobotLinkFlags::links(const kinematics::SerialChain* remembered) const {
  // A model remembers the links its URDF robot was taken between: the defaults of a URDF named
  // again; a link given now replaces both.
  if (remembered != nullptr && tip_link.empty() && base_link.empty()) {
    return {remembered->urdf_base_link(), remembered->urdf_tip_link(), true};
  }
  return {base_link, tip_link};
}

kinematics::SerialChain robot_from_args(const std::string& robot,
                                        const std::vector<double>& tool_mm,
                                        const io::UrdfChainOptions& links) {
  kinematics::SerialChain chain = io::load_robot(robot, links);
  if (tool_mm.empty()) return chain;
  check_finite(tool_mm, "--tool-mm");
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
  tool.translation() << units::mm_to_m(tool_mm[0]), units::mm_to_m(tool_mm[1]),
      units::mm_to_m(tool_mm[2]);
  return chain.with_tool(tool);
}

std::string pose_frame_description(const kinematics::SerialChain& chain) {
  const bool tool = chain.T_flange_tcp().matrix() != Eigen::Matrix4d::Identity();
  const bool base = chain.T_base_dh0().matrix() != Eigen::Matrix4d::Identity();
  std::string s = tool ? "TCP (flange + tool offset " +
                             xyz_mm_text(chain.T_flange_tcp().translation(), 3) + " mm)"
                       : "flange (last DH frame)";
  s += base ? " in the robot base frame" : " in the DH base frame";
  return s;
}

void pose_to_json(const Eigen::Isometry3d& pose, nlohmann::json& j) {
  const Eigen::Vector3d p = pose.translation();
  j["xyz_mm"] = {units::m_to_mm(p.x()), units::m_to_mm(p.y()), units::m_to_mm(p.z())};
  const Eigen::Vector3d rpy = kinematics::rpy_from_rotation(pose.linear());
  j["rpy_deg"] = {units::rad_to_deg(rpy(0)), units::rad_to_deg(rpy(1)), units::rad_to_deg(rpy(2))};
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) {
    rows.push_back({pose.linear()(r, 0), pose.linear()(r, 1), pose.linear()(r, 2)});
  }
  j["rotation"] = rows;
}

std::string xyz_mm_text(const Eigen::Vector3d& metres, int decimals) {
  return format_mm(metres.x(), decimals) + " " + format_mm(metres.y(), decimals) + " " +
         format_mm(metres.z(), decimals);
}

std::string rpy_deg_text(const Eigen::Matrix3d& rotation, int decimals) {
  const Eigen::Vector3d rpy = kinematics::rpy_from_rotation(rotation);
  return format_fixed(units::rad_to_deg(rpy(0)), decimals) + " " +
         format_fixed(units::rad_to_deg(rpy(1)), decimals) + " " +
         format_fixed(units::rad_to_deg(rpy(2)), decimals);
}

nlohmann::json singular_json(std::uint8_t flags) {
  nlohmann::json names = nlohmann::json::array();
  if ((flags & kinematics::kWristSingular) != 0) names.push_back("wrist");
  if ((flags & kinematics::kShoulderSingular) != 0) names.push_back("shoulder");
  if ((flags & kinematics::kElbowSingular) != 0) names.push_back("elbow");
  if ((flags & kinematics::kArmAngleSingular) != 0) names.push_back("arm-angle");
  return names;
}

nlohmann::json degrees_json(const Eigen::Ref<const Eigen::VectorXd>& q_rad) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < q_rad.size(); ++i) out.push_back(units::rad_to_deg(q_rad(i)));
  return out;
}

}  // namespace vrreg::cli

namespace vrreg::cli {

double shown_joint_value(const kinematics::SerialChain& chain, int i, double q) {
  return chain.prismatic(i) ? units::m_to_mm(q) : units::rad_to_deg(q);
}

nlohmann::json shown_joints_json(const kinematics::SerialChain& chain,
                                 const Eigen::Ref<const Eigen::VectorXd>& q) {
  nlohmann::json out = nlohmann::json::array();
  for (int i = 0; i < chain.n_joints(); ++i) out.push_back(shown_joint_value(chain, i, q(i)));
  return out;
}

nlohmann::json joint_names_json(const kinematics::SerialChain& chain) {
  nlohmann::json out = nlohmann::json::array();
  for (const kinematics::JointVariable& v : chain.couplings().variables) out.push_back(v.name);
  return out;
}

std::string coupled_joints_text(const kinematics::SerialChain& chain) {
  const kinematics::JointCouplings& c = chain.couplings();
  std::string out;
  for (std::size_t v = 0; v < c.variables.size(); ++v) {
    out += (out.empty() ? "q" : ", q") + std::to_string(v + 1) + " " + c.variables[v].name;
  }
  std::string followers;
  for (std::size_t r = 0; r < c.rows.size(); ++r) {
    const kinematics::JointCoupling& k = c.rows[r];
    if (k.multiplier == 1.0 && k.offset == 0.0) continue;
    followers += (followers.empty() ? "" : ", ") + std::string("row ") + std::to_string(r + 1) +
                 " = " + format_general(k.multiplier, 6) + " q" + std::to_string(k.variable + 1);
    if (k.offset != 0.0) followers += " + " + format_general(k.offset, 6);
  }
  return followers.empty() ? out : out + " (" + followers + ")";
}

std::string prismatic_note(const kinematics::SerialChain& chain) {
  std::string joints;
  for (int i = 0; i < chain.n_joints(); ++i) {
    if (chain.prismatic(i)) joints += (joints.empty() ? "q" : ", q") + std::to_string(i + 1);
  }
  return joints.empty() ? "" : " (" + joints + " in mm: prismatic)";
}

}  // namespace vrreg::cli
