// SPDX-License-Identifier: Apache-2.0
#include "model_chain_json.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "vrreg/core/check.hpp"

namespace vrreg::io::detail {
namespace {

using ojson = nlohmann::ordered_json;

ojson finite_row(const std::vector<double>& values, const char* what, const char* key) {
  ojson out = ojson::array();
  for (const double v : values) {
    VRREG_THROW_UNLESS(std::isfinite(v), "model: " << what << " " << key << " is not finite");
    out.push_back(v);
  }
  return out;
}

ojson matrix_json(const Eigen::Matrix4d& m, const char* what, const char* key) {
  ojson out = ojson::array();
  for (int r = 0; r < 4; ++r) out.push_back(finite_row({m(r, 0), m(r, 1), m(r, 2), m(r, 3)}, what, key));
  return out;
}

Eigen::Isometry3d read_matrix(const nlohmann::json& robot, const std::string& robot_path,
                              const char* key, const JsonFields& f) {
  const nlohmann::json& rows = f.member(robot, robot_path, key);
  if (!rows.is_array() || rows.size() != 4) f.fail(join_path(robot_path, key), "expected 4 rows of 4 numbers");
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    const std::vector<double> row = f.array_of_numbers(
        rows[static_cast<std::size_t>(r)], join_path(robot_path, key) + "[" + std::to_string(r) + "]", 4);
    for (int c = 0; c < 4; ++c) m(r, c) = row[static_cast<std::size_t>(c)];
  }
  return Eigen::Isometry3d(m);
}

kinematics::JointCouplings read_couplings(const nlohmann::json& robot,
                                          const std::string& robot_path, std::size_t n_rows,
                                          const JsonFields& f) {
  const std::string rows_path = join_path(robot_path, "joint_couplings");
  const std::string variables_path = join_path(robot_path, "joint_variables");
  const nlohmann::json& rows = f.member(robot, robot_path, "joint_couplings");
  const nlohmann::json& variables = f.member(robot, robot_path, "joint_variables");
  if (!rows.is_array() || rows.size() != n_rows)
    f.fail(rows_path, "expected one object per DH row");
  if (!variables.is_array() || variables.empty() || variables.size() > n_rows) {
    f.fail(variables_path, "expected 1 to one-per-DH-row joint variables");
  }
  kinematics::JointCouplings out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string at = rows_path + "[" + std::to_string(i) + "]";
    f.require_object(rows[i], at);
    out.rows.push_back({f.integer(rows[i], at, "variable"), f.number(rows[i], at, "multiplier"),
                        f.number(rows[i], at, "offset")});
  }
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const std::string at = variables_path + "[" + std::to_string(i) + "]";
    f.require_object(variables[i], at);
    kinematics::JointVariable v;
    v.name = f.string(variables[i], at, "name");
    const std::string type = f.string(variables[i], at, "type");
    if (type != "revolute" && type != "prismatic") {
      f.fail(join_path(at, "type"), "expected \"revolute\" or \"prismatic\"");
    }
    if (type == "prismatic") v.type = kinematics::JointType::kPrismatic;
    const std::vector<double> l = f.numbers(variables[i], at, "limits_rad", 2);
    v.limits = {l[0], l[1]};
    out.variables.push_back(std::move(v));
  }
  return out;
}

}  // namespace

ojson chain_json(const kinematics::SerialChain& chain, bool with_tool, const char* what) {
  ojson robot = ojson::object();
  robot["name"] = chain.name();
  ojson dh = ojson::array();
  for (const kinematics::DhRow& row : chain.rows()) {
    dh.push_back(finite_row({row.a_m, row.alpha_rad, row.d_m, row.theta_offset_rad}, what, "dh"));
  }
  robot["dh_a_m_alpha_rad_d_m_theta_offset_rad"] = std::move(dh);
  ojson limits = ojson::array();
  for (const kinematics::JointLimits& l : chain.limits()) {
    limits.push_back(finite_row({l.lower_rad, l.upper_rad}, what, "joint_limits_rad"));
  }
  robot["joint_limits_rad"] = std::move(limits);
  // Only a chain with a prismatic joint says which joints are which (older files have none).
  const auto& rows = chain.rows();
  const auto slides = [](const kinematics::DhRow& r) { return r.prismatic(); };
  if (std::any_of(rows.begin(), rows.end(), slides)) {
    ojson types = ojson::array();
    for (const kinematics::DhRow& row : rows) {
      types.push_back(row.prismatic() ? "prismatic" : "revolute");
    }
    robot["joint_types"] = std::move(types);
  }
  // Only a chain with joints that follow others (URDF mimic) says how (older files have none).
  if (chain.coupled()) {
    ojson couplings = ojson::array();
    for (const kinematics::JointCoupling& c : chain.couplings().rows) {
      couplings.push_back({{"variable", c.variable},
                           {"multiplier", finite_row({c.multiplier}, what, "multiplier")[0]},
                           {"offset", finite_row({c.offset}, what, "offset")[0]}});
    }
    robot["joint_couplings"] = std::move(couplings);
    ojson variables = ojson::array();
    for (const kinematics::JointVariable& v : chain.couplings().variables) {
      variables.push_back(
          {{"name", v.name},
           {"type", v.type == kinematics::JointType::kPrismatic ? "prismatic" : "revolute"},
           {"limits_rad", finite_row({v.limits.lower_rad, v.limits.upper_rad}, what, "limits")}});
    }
    robot["joint_variables"] = std::move(variables);
  }
  if (!chain.urdf_tip_link().empty()) {
    robot["urdf_base_link"] = chain.urdf_base_link();
    robot["urdf_tip_link"] = chain.urdf_tip_link();
  }
  robot["T_base_dh0_m"] = matrix_json(chain.T_base_dh0().matrix(), what, "T_base_dh0");
  if (with_tool) robot["T_flange_tcp_m"] = matrix_json(chain.T_flange_tcp().matrix(), what, "T_flange_tcp");
  return robot;
}

kinematics::SerialChain read_chain(const nlohmann::json& robot, const std::string& robot_path,
                                   const JsonFields& f) {
  f.require_object(robot, robot_path);
  const std::string name = f.string(robot, robot_path, "name");
  const std::string dh_key = "dh_a_m_alpha_rad_d_m_theta_offset_rad";
  const nlohmann::json& dh = f.member(robot, robot_path, dh_key);
  const nlohmann::json& limits = f.member(robot, robot_path, "joint_limits_rad");
  if (!dh.is_array() || dh.empty() || dh.size() > kinematics::kMaxJoints) {
    f.fail(join_path(robot_path, dh_key), "expected 1 to 12 rows of 4 numbers");
  }
  if (!limits.is_array() || limits.size() != dh.size()) {
    f.fail(join_path(robot_path, "joint_limits_rad"), "expected one [lower, upper] per DH row");
  }
  std::vector<kinematics::DhRow> rows;
  std::vector<kinematics::JointLimits> joint_limits;
  for (std::size_t i = 0; i < dh.size(); ++i) {
    const std::string at = "[" + std::to_string(i) + "]";
    const std::vector<double> r = f.array_of_numbers(dh[i], join_path(robot_path, dh_key) + at, 4);
    rows.push_back({r[0], r[1], r[2], r[3]});
    const std::vector<double> l =
        f.array_of_numbers(limits[i], join_path(robot_path, "joint_limits_rad") + at, 2);
    joint_limits.push_back({l[0], l[1]});
  }
  if (robot.contains("joint_types")) {
    const nlohmann::json& types = robot.at("joint_types");
    const std::string path = join_path(robot_path, "joint_types");
    if (!types.is_array() || types.size() != rows.size()) {
      f.fail(path, "expected one type per DH row");
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (types[i] != "revolute" && types[i] != "prismatic") {
        f.fail(path + "[" + std::to_string(i) + "]", "expected \"revolute\" or \"prismatic\"");
      }
      if (types[i] == "prismatic") rows[i].type = kinematics::JointType::kPrismatic;
    }
  }
  const Eigen::Isometry3d T_base_dh0 = read_matrix(robot, robot_path, "T_base_dh0_m", f);
  const Eigen::Isometry3d T_flange_tcp = robot.contains("T_flange_tcp_m")
                                             ? read_matrix(robot, robot_path, "T_flange_tcp_m", f)
                                             : Eigen::Isometry3d::Identity();
  try {
    kinematics::SerialChain chain(name, rows, joint_limits, T_base_dh0, T_flange_tcp);
    if (robot.contains("joint_couplings") || robot.contains("joint_variables")) {
      chain = chain.with_couplings(read_couplings(robot, robot_path, rows.size(), f));
    }
    if (robot.contains("urdf_tip_link") || robot.contains("urdf_base_link")) {
      chain = chain.with_urdf_links(f.string(robot, robot_path, "urdf_base_link"),
                                    f.string(robot, robot_path, "urdf_tip_link"));
    }
    return chain;
  } catch (const InputError& e) {
    f.fail(robot_path, e.what());
  }
}

}  // namespace vrreg::io::detail
