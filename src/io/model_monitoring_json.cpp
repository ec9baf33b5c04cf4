// SPDX-License-Identifier: Apache-2.0
#include "model_monitoring_json.hpp"

#include <cmath>
#include <sstream>

#include "vrreg/core/check.hpp"

namespace vrreg::io::detail {
namespace {

using ordered_json = nlohmann::ordered_json;
using nlohmann::json;

ordered_json vector_json(const Eigen::Vector3d& v, const char* key) {
  VRREG_THROW_UNLESS(v.allFinite(), "model: " << key << " is not finite");
  return ordered_json::array({v(0), v(1), v(2)});
}

ordered_json monitor_json(const Location& m) {
  ordered_json out = ordered_json::object();
  out["point"] = m.point;
  out["config"] = m.config ? ordered_json(*m.config) : ordered_json(nullptr);
  out["visit"] = m.visit ? ordered_json(*m.visit) : ordered_json(nullptr);
  out["robot_m"] = vector_json(m.robot_m, "monitor robot_m");
  out["sensor_m"] = vector_json(m.sensor_m, "monitor sensor_m");
  out["n_readings"] = m.n_readings;
  if (!m.q_rad.empty()) out["q_rad"] = m.q_rad;
  return out;
}

Location read_monitor(const json& item, const std::string& path, const JsonFields& f,
                      const LengthUnits& u) {
  f.require_object(item, path);
  Location m;
  m.role = Role::kMonitor;
  m.point = f.string(item, path, "point");
  if (m.point.empty()) f.fail(join_path(path, "point"), "empty point label");
  m.config = f.optional_integer(item, path, "config");
  m.visit = f.optional_integer(item, path, "visit");
  m.robot_m = f.vector3(item, path, u.key("robot"), u.per_m);
  m.sensor_m = f.vector3(item, path, u.key("sensor"), u.per_m);
  m.n_readings = f.integer(item, path, "n_readings");
  if (m.n_readings < 1) f.fail(join_path(path, "n_readings"), "must be at least 1");
  if (item.contains("q_rad")) m.q_rad = f.numbers(item, path, "q_rad", -1);
  return m;
}

}  // namespace

void add_monitoring_json(const RegistrationModel& model, ordered_json& out) {
  if (!model.monitors.empty()) {
    ordered_json monitors = ordered_json::array();
    for (const Location& m : model.monitors) monitors.push_back(monitor_json(m));
    out["monitors"] = std::move(monitors);
  }
  if (model.T_registered_sensor) {
    const RigidTransform& M = *model.T_registered_sensor;
    ordered_json rotation = ordered_json::array();
    for (int r = 0; r < 3; ++r)
      rotation.push_back(vector_json(M.rotation.row(r).transpose(), "T_registered_sensor"));
    out["T_registered_sensor"] = {
        {"rotation", std::move(rotation)},
        {"translation_m", vector_json(M.translation_m, "T_registered_sensor")}};
  }
  if (!model.lineage.empty()) {
    ordered_json lineage = ordered_json::array();
    for (const ModelUpdate& u : model.lineage) {
      VRREG_THROW_UNLESS(std::isfinite(u.fit_rms_m), "model: lineage fit_rms_m is not finite");
      lineage.push_back({{"change", u.change},
                         {"parent", u.parent},
                         {"points_source", u.points_source},
                         {"points", u.points},
                         {"time", u.time},
                         {"fit_rms_m", u.fit_rms_m}});
    }
    out["lineage"] = std::move(lineage);
  }
}

void read_monitoring(const json& doc, const JsonFields& f, const LengthUnits& u,
                     RegistrationModel& model) {
  if (doc.contains("monitors")) {
    const json& monitors = doc.at("monitors");
    if (!monitors.is_array()) f.fail("monitors", "expected an array");
    for (std::size_t k = 0; k < monitors.size(); ++k)
      model.monitors.push_back(
          read_monitor(monitors[k], "monitors[" + std::to_string(k) + "]", f, u));
  }
  if (doc.contains("T_registered_sensor")) {
    const json& item = doc.at("T_registered_sensor");
    f.require_object(item, "T_registered_sensor");
    const json& rows = f.member(item, "T_registered_sensor", "rotation");
    if (!rows.is_array() || rows.size() != 3)
      f.fail("T_registered_sensor.rotation", "expected 3 rows of 3 numbers");
    RigidTransform M;
    for (int r = 0; r < 3; ++r) {
      const std::vector<double> row =
          f.array_of_numbers(rows[static_cast<std::size_t>(r)],
                             "T_registered_sensor.rotation[" + std::to_string(r) + "]", 3);
      for (int c = 0; c < 3; ++c) M.rotation(r, c) = row[static_cast<std::size_t>(c)];
    }
    const double orthogonality =
        (M.rotation.transpose() * M.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (orthogonality > 1e-9 || M.rotation.determinant() < 0.0)
      f.fail("T_registered_sensor.rotation", "not a proper rotation");
    M.translation_m = f.vector3(item, "T_registered_sensor", "translation_m", 1.0);
    model.T_registered_sensor = M;
  }
  if (doc.contains("lineage")) {
    const json& lineage = doc.at("lineage");
    if (!lineage.is_array()) f.fail("lineage", "expected an array");
    for (std::size_t k = 0; k < lineage.size(); ++k) {
      const std::string path = "lineage[" + std::to_string(k) + "]";
      const json& item = lineage[k];
      f.require_object(item, path);
      ModelUpdate entry;
      entry.change = f.string(item, path, "change");
      if (entry.change != "bump" && entry.change != "drift")
        f.fail(join_path(path, "change"), "expected \"bump\" or \"drift\"");
      entry.parent = f.string(item, path, "parent");
      entry.points_source = f.string(item, path, "points_source");
      entry.time = f.string(item, path, "time");
      entry.fit_rms_m = f.number(item, path, "fit_rms_m");
      const json& points = f.member(item, path, "points");
      if (!points.is_array()) f.fail(join_path(path, "points"), "expected an array of names");
      for (const json& p : points) {
        if (!p.is_string()) f.fail(join_path(path, "points"), "expected an array of names");
        entry.points.push_back(p.get<std::string>());
      }
      model.lineage.push_back(std::move(entry));
    }
  }
}

}  // namespace vrreg::io::detail
