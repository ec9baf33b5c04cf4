// SPDX-License-Identifier: Apache-2.0
#include "http_api.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "line_protocol.hpp"
#include "service.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/io/json_text.hpp"

namespace vrreg::serve {
namespace {

using nlohmann::json;

constexpr double kMaxAbsCoordinateMm = 1e9;

struct Refused {
  std::string reason;
};

double number_at(const json& v, const std::string& where) {
  if (!v.is_number()) throw Refused{where + ": expected a number"};
  const double x = v.get<double>();
  if (!std::isfinite(x) || std::abs(x) > kMaxAbsCoordinateMm) throw Refused{where + ": not a finite number within 1e9"};
  return x;
}

// The angles [rad] under `key`, when the item has it.
void read_angles(const json& item, const char* key, const std::string& where,
                 std::vector<double>& out) {
  const auto q = item.find(key);
  if (q == item.end()) return;
  if (!q->is_array() || q->empty() || q->size() > 16) {
    throw Refused{where + "." + key + ": expected 1 to 16 angles in rad"};
  }
  for (const json& v : *q) {
    const double angle = number_at(v, where + "." + key);
    if (std::abs(angle) > 100.0) throw Refused{where + "." + key + ": not an angle in rad"};
    out.push_back(angle);
  }
}

void read_point(const json& item, const std::string& where, PointRequest& out) {
  if (!item.is_object()) throw Refused{where + ": expected an object"};
  for (const auto& [key, value] : item.items()) {
    if (key != "model" && key != "sensor_mm" && key != "joints_rad" && key != "config" &&
        key != "extrapolate" && key != "points" && key != "sensor_q" && key != "from_rad" &&
        key != "approach") {
      throw Refused{where + ": unknown key '" + key + "'"};
    }
  }
  const auto s = item.find("sensor_mm");
  if (s == item.end() || !s->is_array() || s->size() != 3) {
    throw Refused{where + ".sensor_mm: expected [x, y, z] in mm"};
  }
  for (int a = 0; a < 3; ++a) {
    out.sensor_mm(a) = number_at((*s)[static_cast<std::size_t>(a)], where + ".sensor_mm");
  }
  read_angles(item, "joints_rad", where, out.joints_rad);
  read_angles(item, "from_rad", where, out.from_rad);
  if (!out.from_rad.empty()) {
    if (item.contains("approach")) throw Refused{where + ": give from_rad or approach, not both"};
    if (out.joints_rad.empty()) {
      throw Refused{where + ".from_rad: needs joints_rad (the approach is joints - from)"};
    }
    if (out.from_rad.size() != out.joints_rad.size()) {
      throw Refused{where + ".from_rad: " + std::to_string(out.from_rad.size()) +
                    " angles, joints_rad " + std::to_string(out.joints_rad.size())};
    }
    out.approach_sign = approach_sign_of_move(out.from_rad, out.joints_rad);
  }
  if (const auto a = item.find("approach"); a != item.end()) {
    if (!a->is_array() || a->empty() || a->size() > 16) {
      throw Refused{where + ".approach: expected 1 to 16 signs (-1, 0 or 1)"};
    }
    for (const json& v : *a) {
      const double sign = number_at(v, where + ".approach");
      if (sign != -1.0 && sign != 0.0 && sign != 1.0) {
        throw Refused{where + ".approach: a sign is -1, 0 or 1"};
      }
      out.approach_sign.push_back(sign == 0.0 ? 0.0 : sign);
    }
    if (!out.joints_rad.empty() && out.approach_sign.size() != out.joints_rad.size()) {
      throw Refused{where + ".approach: " + std::to_string(out.approach_sign.size()) +
                    " signs, joints_rad " + std::to_string(out.joints_rad.size())};
    }
  }
  if (const auto c = item.find("config"); c != item.end()) {
    if (!c->is_number_integer()) throw Refused{where + ".config: expected an integer label"};
    const auto label = c->get<long long>();
    if (label < -1000000 || label > 1000000) throw Refused{where + ".config: out of range"};
    out.config = static_cast<int>(label);
  }
  if (const auto e = item.find("extrapolate"); e != item.end()) {
    if (!e->is_boolean()) throw Refused{where + ".extrapolate: expected true or false"};
    out.extrapolate = e->get<bool>();
  }
  if (const auto q = item.find("sensor_q"); q != item.end()) {
    if (!q->is_array() || q->size() != 4) {
      throw Refused{where + ".sensor_q: expected the marker's orientation [qx, qy, qz, qw]"};
    }
    Eigen::Vector4d xyzw;
    for (int k = 0; k < 4; ++k) {
      xyzw(k) = number_at((*q)[static_cast<std::size_t>(k)], where + ".sensor_q");
    }
    try {
      out.q_sensor_marker = unit_quaternion(xyzw, (where + ".sensor_q").c_str());
    } catch (const InputError& e) {
      throw Refused{e.what()};
    }
    out.orientation_form = OrientationForm::kQuaternion;
  }
}

json mm3_json(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json quaternion_json(const Eigen::Quaterniond& q) {
  const Eigen::VectorXd xyzw = orientation_in(q, OrientationForm::kQuaternion);
  return json::array({xyzw(0), xyzw(1), xyzw(2), xyzw(3)});
}

json answer_object(const PointAnswer& a) {
  json j;
  j["status"] = a.status;
  j["code"] = static_cast<int>(a.code);
  if (a.code == ReplyCode::kOk) {
    j["robot_mm"] = mm3_json(a.robot_mm);
    j["uncorrected_robot_mm"] = mm3_json(a.uncorrected_robot_mm);
    j["predicted_sd_mm"] = a.sd_mm;
    if (a.q_robot_marker) {
      j["robot_q"] = quaternion_json(*a.q_robot_marker);
      j["uncorrected_robot_q"] = quaternion_json(a.uncorrected_q_robot_marker.value());
      j["rotation_applied_mrad"] = mm3_json(1e3 * a.rotation_applied_rad);
      j["predicted_angle_sd_mrad"] = 1e3 * a.angle_sd_rad;
    }
  } else {
    j["error"] = a.reason;
    if (a.code == ReplyCode::kNotCorrectable || a.code == ReplyCode::kTooFar) {
      j["uncorrected_robot_mm"] = mm3_json(a.uncorrected_robot_mm);
    }
  }
  return j;
}

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

}  // namespace

std::variant<HttpCorrectRequest, PointAnswer> parse_http_correct(std::string_view body,
                                                                std::size_t max_batch) {
  json doc;
  try {  // within the limits of vrreg's JSON files: nesting, number range, UTF-8
    doc = io::parse_json_document(std::string(body), "request body", "correction request");
  } catch (const FileError& e) {
    return PointAnswer::refusal(ReplyCode::kMalformed, e.what());
  }
  try {
    if (!doc.is_object()) throw Refused{"body: expected an object"};
    const auto m = doc.find("model");
    if (m == doc.end() || !m->is_string()) throw Refused{"model: expected the model's name"};
    HttpCorrectRequest out;
    PointRequest common;
    common.model = m->get<std::string>();
    if (const auto p = doc.find("points"); p != doc.end()) {
      out.batch = true;
      if (!p->is_array()) throw Refused{"points: expected an array"};
      if (p->empty()) throw Refused{"points: an empty batch (give at least one point)"};
      for (const auto& [key, value] : doc.items()) {
        if (key != "model" && key != "points" && key != "extrapolate") {
          throw Refused{"body: unknown key '" + key + "' beside points"};
        }
      }
      if (p->size() > max_batch) {
        return PointAnswer::refusal(ReplyCode::kLimit, "points: " + std::to_string(p->size()) +
                                                           " in one batch, at most " +
                                                           std::to_string(max_batch));
      }
      if (doc.contains("sensor_mm")) throw Refused{"body: give sensor_mm or points, not both"};
      if (const auto e = doc.find("extrapolate"); e != doc.end()) {
        if (!e->is_boolean()) throw Refused{"extrapolate: expected true or false"};
        common.extrapolate = e->get<bool>();
      }
      for (std::size_t i = 0; i < p->size(); ++i) {
        PointRequest point = common;
        const json& item = (*p)[i];
        if (item.is_object() && (item.contains("model") || item.contains("points"))) {
          throw Refused{"points[" + std::to_string(i) + "]: model and points belong to the body"};
        }
        read_point(item, "points[" + std::to_string(i) + "]", point);
        out.points.push_back(std::move(point));
      }
    } else {
      PointRequest point = common;
      read_point(doc, "body", point);
      out.points.push_back(std::move(point));
    }
    return out;
  } catch (const Refused& r) {
    return PointAnswer::refusal(ReplyCode::kMalformed, r.reason);
  } catch (const std::exception& e) {  // a number nlohmann cannot convert, ...
    return PointAnswer::refusal(ReplyCode::kMalformed, e.what());
  }
}

int http_status(ReplyCode code) {
  switch (code) {
    case ReplyCode::kOk: return 200;
    case ReplyCode::kMalformed: return 400;
    case ReplyCode::kUnauthorized: return 401;
    case ReplyCode::kUnknownModel: return 404;
    case ReplyCode::kLimit: return 413;
    case ReplyCode::kNotCorrectable:
    case ReplyCode::kInput:
    case ReplyCode::kTooFar: return 422;
    case ReplyCode::kInternal: return 500;
  }
  return 500;
}

std::string answer_json(const PointAnswer& answer, const ModelIdentity* model) {
  json j = answer_object(answer);
  if (model) {
    j["model"] = model->name;
    j["sha256"] = model->sha256;
  }
  return dump(j);
}

std::string batch_json(const std::vector<PointAnswer>& answers, const ModelIdentity& model) {
  json j;
  j["model"] = model.name;
  j["sha256"] = model.sha256;
  json results = json::array();
  for (const PointAnswer& a : answers) results.push_back(answer_object(a));
  j["results"] = std::move(results);
  return dump(j);
}

std::string health_json(const std::vector<std::shared_ptr<const ServedModel>>& models,
                        const std::vector<std::string>& reload_errors,
                        const std::string& audit_error, const ServiceStats& stats) {
  json j;
  j["status"] = "ready";
  json list = json::array();
  for (std::size_t i = 0; i < models.size(); ++i) {
    const ModelIdentity& id = models[i]->identity();
    json m;
    m["name"] = id.name;
    m["file"] = id.path;
    m["sha256"] = id.sha256;
    m["file_time"] = id.file_time_utc;
    m["loaded_at"] = id.loaded_at_utc;
    m["method"] = id.method;
    m["n_fiducials"] = id.n_fiducials;
    m["predicts_sd"] = id.predicts_sd;
    m["corrects_orientation"] = id.corrects_orientation;
    // Always there, null when the last reload (if any) succeeded: a client reads one shape.
    m["last_reload_error"] = i < reload_errors.size() && !reload_errors[i].empty()
                                 ? json(reload_errors[i])
                                 : json(nullptr);
    list.push_back(std::move(m));
  }
  j["models"] = std::move(list);
  if (!audit_error.empty()) j["audit_log_error"] = audit_error;
  j["counters"] = {{"corrections", stats.corrections},
                   {"refusals", stats.refusals},
                   {"malformed_requests", stats.malformed},
                   {"unauthorized_requests", stats.unauthorized},
                   {"limited_requests", stats.limited},
                   {"connections", stats.connections},
                   {"rejected_connections", stats.rejected_connections},
                   {"open_line_connections", stats.open_line_connections},
                   {"open_http_connections", stats.open_http_connections}};
  return dump(j);
}

}  // namespace vrreg::serve
