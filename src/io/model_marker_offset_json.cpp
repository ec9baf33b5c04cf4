// SPDX-License-Identifier: Apache-2.0
#include "model_marker_offset_json.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "model_chain_json.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::io::detail {
namespace {

using ojson = nlohmann::ordered_json;

ojson finite_array(const std::vector<double>& values, const char* key) {
  ojson out = ojson::array();
  for (const double v : values) {
    VRREG_THROW_UNLESS(std::isfinite(v), "model: marker_offset " << key << " is not finite");
    out.push_back(v);
  }
  return out;
}

ojson m3(const Eigen::Vector3d& v_m, const char* key) {
  return finite_array({v_m.x(), v_m.y(), v_m.z()}, key);
}

}  // namespace

ojson marker_offset_json(const MarkerOffsetModel& offset) {
  ojson out = ojson::object();
  out["p_flange_marker_m"] = m3(offset.p_flange_marker_m, "p_flange_marker_m");
  out["p_std_m"] = m3(offset.p_std_m, "p_std_m");
  out["flange_robot"] = chain_json(offset.flange_chain, false, "marker_offset flange_robot");
  return out;
}

MarkerOffsetModel read_marker_offset(const nlohmann::json& item, const std::string& path,
                                     const JsonFields& f, const LengthUnits& units) {
  f.require_object(item, path);
  const Eigen::Vector3d p = f.vector3(item, path, units.key("p_flange_marker"), units.per_m);
  const Eigen::Vector3d std_m = f.vector3(item, path, units.key("p_std"), units.per_m);
  if (std_m.minCoeff() < 0.0) f.fail(join_path(path, units.key("p_std")), "negative");
  kinematics::SerialChain chain =
      read_chain(f.member(item, path, "flange_robot"), join_path(path, "flange_robot"), f);
  return MarkerOffsetModel{p, std_m, std::move(chain)};
}

}  // namespace vrreg::io::detail
