// SPDX-License-Identifier: Apache-2.0
#include "vrreg/robot_io/error_model_file.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "robot_file_document.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/io/json_text.hpp"

namespace vrreg::io {
namespace {

using nlohmann::json;
using units::deg_to_rad;
using units::m_to_mm;
using units::mm_to_m;
using units::rad_to_deg;

constexpr const char* kFormat = "vrreg-simulation-errors";
constexpr double kArcminPerDegree = 60.0;

// A value in file units, rounded to 12 significant digits so that unit conversions do not show
// up as 14.999999999999998 (and writing what was read gives the same text).
double human(double value) { return std::strtod(format_general(value, 12).c_str(), nullptr); }

json list(const std::vector<double>& values, double scale) {
  json out = json::array();
  for (double v : values) out.push_back(human(v * scale));
  return out;
}

// Reads one document over defaults; every error names file, line (YAML) and key path.
class ErrorModelReader {
 public:
  ErrorModelReader(const detail::RobotDocument& doc, std::string source)
      : doc_(doc), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    doc_.fail(source_, path, message);
  }

  const json* object(const json& parent, const std::string& path, const char* key,
                     const std::set<std::string>& allowed) const {
    const std::string where = join(path, key);
    if (!parent.contains(key)) return nullptr;
    const json& value = parent.at(key);
    if (!value.is_object())
      fail(where, "expected an object with named keys, got " + quote_value(value));
    for (const auto& item : value.items()) {
      if (allowed.count(item.key()) == 0) {
        std::string names;
        for (const std::string& k : allowed) names += (names.empty() ? "" : ", ") + k;
        fail(join(where, item.key()), "unknown key (allowed here: " + names + ")");
      }
    }
    return &value;
  }

  void number(const json& parent, const std::string& path, const char* key, double scale,
              double& out) const {
    if (!parent.contains(key)) return;
    out = scale * finite(parent.at(key), join(path, key));
  }

  void numbers(const json& parent, const std::string& path, const char* key, double scale,
               std::size_t n, std::vector<double>& out) const {
    if (!parent.contains(key)) return;
    const json& value = parent.at(key);
    const std::string where = join(path, key);
    if (!value.is_array() || (value.size() != n && !value.empty())) {
      fail(where, "expected a list of " + std::to_string(n) +
                      " numbers (one per joint) or [], got " + quote_value(value));
    }
    out.clear();
    for (std::size_t i = 0; i < value.size(); ++i) {
      out.push_back(scale * finite(value[i], where + "[" + std::to_string(i) + "]"));
    }
  }

  void boolean(const json& parent, const std::string& path, const char* key, bool& out) const {
    if (!parent.contains(key)) return;
    const json& value = parent.at(key);
    if (!value.is_boolean())
      fail(join(path, key), "expected true or false, got " + quote_value(value));
    out = value.get<bool>();
  }

  void integer(const json& parent, const std::string& path, const char* key, int& out) const {
    if (!parent.contains(key)) return;
    const json& value = parent.at(key);
    if (!value.is_number_integer() || value.get<std::int64_t>() < 1 ||
        value.get<std::int64_t>() > 1000000) {
      fail(join(path, key), "expected an integer in [1, 1000000], got " + quote_value(value));
    }
    out = value.get<int>();
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

 private:
  double finite(const json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "expected a number, got " + quote_value(value));
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(path, "not a finite number");
    return x;
  }

  const detail::RobotDocument& doc_;
  std::string source_;
};

void read_robot(const ErrorModelReader& reader, const json& root, std::size_t n_joints,
                simulation::RobotErrorModel& r) {
  const json* robot = reader.object(
      root, "", "robot",
      {"joint_offset_sigma_deg", "link_length_sigma_mm", "link_offset_sigma_mm", "twist_sigma_deg",
       "transmission_amplitude_arcmin", "transmission_period_deg", "repeatability_sigma_mm",
       "compliance", "link_mass_kg", "joint_stiffness_nm_per_rad", "payload_kg",
       "lost_motion_arcmin", "lost_motion_take_up"});
  if (robot == nullptr) return;
  const double deg = deg_to_rad(1.0);
  const double mm = mm_to_m(1.0);
  reader.number(*robot, "robot", "joint_offset_sigma_deg", deg, r.joint_offset_sigma_rad);
  reader.number(*robot, "robot", "link_length_sigma_mm", mm, r.link_length_sigma_m);
  reader.number(*robot, "robot", "link_offset_sigma_mm", mm, r.link_offset_sigma_m);
  reader.number(*robot, "robot", "twist_sigma_deg", deg, r.twist_sigma_rad);
  reader.numbers(*robot, "robot", "transmission_amplitude_arcmin", deg / kArcminPerDegree, n_joints,
                 r.transmission_amplitude_rad);
  reader.numbers(*robot, "robot", "transmission_period_deg", deg, n_joints,
                 r.transmission_period_rad);
  reader.number(*robot, "robot", "repeatability_sigma_mm", mm, r.repeatability_sigma_m);
  reader.boolean(*robot, "robot", "compliance", r.compliance);
  reader.numbers(*robot, "robot", "link_mass_kg", 1.0, n_joints, r.link_mass_kg);
  reader.numbers(*robot, "robot", "joint_stiffness_nm_per_rad", 1.0, n_joints,
                 r.joint_stiffness_nm_per_rad);
  reader.number(*robot, "robot", "payload_kg", 1.0, r.payload_kg);
  reader.numbers(*robot, "robot", "lost_motion_arcmin", deg / kArcminPerDegree, n_joints,
                 r.lost_motion_rad);
  reader.number(*robot, "robot", "lost_motion_take_up", 1.0, r.lost_motion_take_up);
}

void read_tracker(const ErrorModelReader& reader, const json& root, simulation::TrackerModel& t) {
  const json* tracker =
      reader.object(root, "", "tracker",
                    {"distance_m", "azimuth_deg", "elevation_deg", "noise_sigma_mm",
                     "readings_per_location", "rigid_body_radius_mm", "rigid_body_markers"});
  if (tracker == nullptr) return;
  reader.number(*tracker, "tracker", "distance_m", 1.0, t.distance_m);
  reader.number(*tracker, "tracker", "azimuth_deg", deg_to_rad(1.0), t.azimuth_rad);
  reader.number(*tracker, "tracker", "elevation_deg", deg_to_rad(1.0), t.elevation_rad);
  std::vector<double> sigma(t.noise_sigma_m.data(), t.noise_sigma_m.data() + 3);
  reader.numbers(*tracker, "tracker", "noise_sigma_mm", mm_to_m(1.0), 3, sigma);
  if (sigma.size() != 3) reader.fail("tracker.noise_sigma_mm", "expected 3 numbers (x, y, z)");
  t.noise_sigma_m = Eigen::Vector3d(sigma[0], sigma[1], sigma[2]);
  reader.integer(*tracker, "tracker", "readings_per_location", t.readings_per_location);
  reader.number(*tracker, "tracker", "rigid_body_radius_mm", mm_to_m(1.0), t.rigid_body_radius_m);
  reader.integer(*tracker, "tracker", "rigid_body_markers", t.rigid_body_markers);
}

}  // namespace

std::string format_error_model(const simulation::TestbedErrorModel& model,
                               const std::string& testbed_name) {
  const simulation::RobotErrorModel& r = model.robot;
  const simulation::TrackerModel& t = model.tracker;
  nlohmann::ordered_json robot;
  robot["joint_offset_sigma_deg"] = human(rad_to_deg(r.joint_offset_sigma_rad));
  robot["link_length_sigma_mm"] = human(m_to_mm(r.link_length_sigma_m));
  robot["link_offset_sigma_mm"] = human(m_to_mm(r.link_offset_sigma_m));
  robot["twist_sigma_deg"] = human(rad_to_deg(r.twist_sigma_rad));
  robot["transmission_amplitude_arcmin"] =
      list(r.transmission_amplitude_rad, rad_to_deg(1.0) * kArcminPerDegree);
  robot["transmission_period_deg"] = list(r.transmission_period_rad, rad_to_deg(1.0));
  robot["repeatability_sigma_mm"] = human(m_to_mm(r.repeatability_sigma_m));
  robot["compliance"] = r.compliance;
  robot["link_mass_kg"] = list(r.link_mass_kg, 1.0);
  robot["joint_stiffness_nm_per_rad"] = list(r.joint_stiffness_nm_per_rad, 1.0);
  robot["payload_kg"] = human(r.payload_kg);
  if (!r.lost_motion_rad.empty()) {  // a robot without lost motion writes what it always did
    robot["lost_motion_arcmin"] = list(r.lost_motion_rad, rad_to_deg(1.0) * kArcminPerDegree);
    robot["lost_motion_take_up"] = human(r.lost_motion_take_up);
  }
  nlohmann::ordered_json tracker;
  tracker["distance_m"] = human(t.distance_m);
  tracker["azimuth_deg"] = human(rad_to_deg(t.azimuth_rad));
  tracker["elevation_deg"] = human(rad_to_deg(t.elevation_rad));
  tracker["noise_sigma_mm"] = {human(m_to_mm(t.noise_sigma_m.x())),
                               human(m_to_mm(t.noise_sigma_m.y())),
                               human(m_to_mm(t.noise_sigma_m.z()))};
  tracker["readings_per_location"] = t.readings_per_location;
  if (t.rigid_body_radius_m > 0.0) {  // a sphere's files stay as they were
    tracker["rigid_body_radius_mm"] = human(m_to_mm(t.rigid_body_radius_m));
    tracker["rigid_body_markers"] = t.rigid_body_markers;
  }
  nlohmann::ordered_json root;
  root["format"] = kFormat;
  root["testbed"] = testbed_name;
  root["robot"] = robot;
  root["tracker"] = tracker;
  return root.dump(2) + "\n";
}

void write_error_model_file(const std::string& path, const simulation::TestbedErrorModel& model,
                            const std::string& testbed_name) {
  write_file_atomically(path, format_error_model(model, testbed_name));
}

simulation::TestbedErrorModel parse_error_model(const std::string& text, const std::string& source,
                                                const simulation::Testbed& testbed) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) throw FileError(source, 0, "empty error-model file");
  const detail::RobotDocument doc = text[first] == '{' || text[first] == '['
                                        ? detail::parse_robot_json(text, source)
                                        : detail::parse_robot_yaml(text, source);
  const ErrorModelReader reader(doc, source);
  const json& root = doc.root;
  if (!root.is_object()) reader.fail("", "expected an object with keys robot and tracker");
  for (const auto& item : root.items()) {
    const std::string& key = item.key();
    if (key != "format" && key != "testbed" && key != "robot" && key != "tracker") {
      reader.fail(key, "unknown key (allowed: format, testbed, robot, tracker)");
    }
  }
  if (root.contains("format") && root.at("format") != kFormat) {
    reader.fail("format",
                std::string("expected \"") + kFormat + "\", got " + quote_value(root.at("format")));
  }
  if (root.contains("testbed") && root.at("testbed") != testbed.name) {
    reader.fail("testbed", "this file is for test bed " + quote_value(root.at("testbed")) +
                               ", not " + testbed.name);
  }
  simulation::TestbedErrorModel model = testbed.default_errors;
  const auto n_joints = static_cast<std::size_t>(testbed.nominal.n_joints());
  read_robot(reader, root, n_joints, model.robot);
  read_tracker(reader, root, model.tracker);
  try {
    model.validate(testbed.nominal.n_joints());
  } catch (const InputError& e) {
    throw FileError(source, 0, e.what());
  }
  return model;
}

simulation::TestbedErrorModel read_error_model_file(const std::string& path,
                                                    const simulation::Testbed& testbed) {
  return parse_error_model(read_input_file(path), path, testbed);
}

}  // namespace vrreg::io
