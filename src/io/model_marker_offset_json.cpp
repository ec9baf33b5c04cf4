#include "model_marker_offset_json.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::io::detail {
namespace {

using ojson = nlohmann::ordered_json;
constexpr double kMmPerM = units::kMillimetresPerMetre;

ojson finite_array(const std::vector<double>& values, const char* key) {
  ojson out = ojson::array();
  for (const double v : values) {
    VRREG_THROW_UNLESS(std::isfinite(v), "model: marker_offset " << key << " is not finite");
    out.push_back(v);
  }
  return out;
}

ojson mm3(const Eigen::Vector3d& v_m, const char* key) {
  return finite_array({kMmPerM * v_m.x(), kMmPerM * v_m.y(), kMmPerM * v_m.z()}, key);
}

}  // namespace

ojson marker_offset_json(const MarkerOffsetModel& offset) {
  const kinematics::SerialChain& chain = offset.flange_chain;
  ojson robot = ojson::object();
  robot["name"] = chain.name();
  ojson dh = ojson::array();
  for (const kinematics::DhRow& row : chain.rows()) {
    dh.push_back(finite_array({row.a_m, row.alpha_rad, row.d_m, row.theta_offset_rad}, "dh"));
  }
  robot["dh_a_m_alpha_rad_d_m_theta_offset_rad"] = std::move(dh);
  ojson limits = ojson::array();
  for (const kinematics::JointLimits& l : chain.limits()) {
    limits.push_back(finite_array({l.lower_rad, l.upper_rad}, "joint_limits_rad"));
  }
  robot["joint_limits_rad"] = std::move(limits);
  ojson base = ojson::array();
  const Eigen::Matrix4d b = chain.T_base_dh0().matrix();
  for (int r = 0; r < 4; ++r) {
    base.push_back(finite_array({b(r, 0), b(r, 1), b(r, 2), b(r, 3)}, "T_base_dh0"));
  }
  robot["T_base_dh0_m"] = std::move(base);
  ojson out = ojson::object();
  out["p_flange_marker_mm"] = mm3(offset.p_flange_marker_m, "p_flange_marker_mm");
  out["p_std_mm"] = mm3(offset.p_std_m, "p_std_mm");
  out["flange_robot"] = std::move(robot);
  return out;
}

MarkerOffsetModel read_marker_offset(const nlohmann::json& item, const std::string& path,
                                     const JsonFields& f) {
  f.require_object(item, path);
  const Eigen::Vector3d p = f.vector3(item, path, "p_flange_marker_mm", kMmPerM);
  const Eigen::Vector3d std_m = f.vector3(item, path, "p_std_mm", kMmPerM);
  if (std_m.minCoeff() < 0.0) f.fail(join_path(path, "p_std_mm"), "negative");
  const std::string robot_path = join_path(path, "flange_robot");
  const nlohmann::json& robot = f.member(item, path, "flange_robot");
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
  const nlohmann::json& base = f.member(robot, robot_path, "T_base_dh0_m");
  if (!base.is_array() || base.size() != 4) {
    f.fail(join_path(robot_path, "T_base_dh0_m"), "expected 4 rows of 4 numbers");
  }
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    const std::vector<double> row = f.array_of_numbers(
        base[static_cast<std::size_t>(r)],
        join_path(robot_path, "T_base_dh0_m") + "[" + std::to_string(r) + "]", 4);
    for (int c = 0; c < 4; ++c) m(r, c) = row[static_cast<std::size_t>(c)];
  }
  Eigen::Isometry3d T_base_dh0(m);
  try {
    return MarkerOffsetModel{p, std_m,
                             kinematics::SerialChain(name, rows, joint_limits, T_base_dh0)};
  } catch (const InputError& e) {
    f.fail(robot_path, e.what());
  }
}

}  // namespace vrreg::io::detail
