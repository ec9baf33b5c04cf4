// SPDX-License-Identifier: Apache-2.0
#include "vrreg/robot_io/model_export.hpp"

#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/pose.hpp"

namespace vrreg::io {
namespace {

constexpr const char* kMarkerDirection =
    "p_flange_marker is the marker's position in the robot's flange (last DH) frame, metres: "
    "p_robot = T_robot_flange(q) p_flange_marker";

std::string number(double v) {
  std::ostringstream out;
  out << std::setprecision(17) << v;
  return out.str();
}

Eigen::Quaterniond quaternion(const RigidTransform& T) {
  Eigen::Quaterniond q(T.rotation);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() *= -1.0;  // one of the two equal quaternions, w >= 0
  return q;
}

std::string yaml_text(const RegistrationModel& model, const RigidTransform& T) {
  const Eigen::Quaterniond q = quaternion(T);
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::Comment(std::string("vrreg export: ") + kTransformDirection) << YAML::Newline;
  out << YAML::BeginMap;
  out << YAML::Key << "direction" << YAML::Value << kTransformDirection;
  out << YAML::Key << "eye_on_hand" << YAML::Value << false;
  out << YAML::Key << "robot_base_frame" << YAML::Value << "robot_base";
  out << YAML::Key << "tracking_base_frame" << YAML::Value << "sensor";
  out << YAML::Key << "transformation" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "x" << YAML::Value << T.translation_m.x();
  out << YAML::Key << "y" << YAML::Value << T.translation_m.y();
  out << YAML::Key << "z" << YAML::Value << T.translation_m.z();
  out << YAML::Key << "qx" << YAML::Value << q.x();
  out << YAML::Key << "qy" << YAML::Value << q.y();
  out << YAML::Key << "qz" << YAML::Value << q.z();
  out << YAML::Key << "qw" << YAML::Value << q.w();
  out << YAML::EndMap;
  if (model.marker_offset) {
    const MarkerOffsetModel& m = *model.marker_offset;
    out << YAML::Key << "marker_offset" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "direction" << YAML::Value << kMarkerDirection;
    out << YAML::Key << "robot_effector_frame" << YAML::Value << "flange";
    out << YAML::Key << "x" << YAML::Value << m.p_flange_marker_m.x();
    out << YAML::Key << "y" << YAML::Value << m.p_flange_marker_m.y();
    out << YAML::Key << "z" << YAML::Value << m.p_flange_marker_m.z();
    out << YAML::Key << "std_x" << YAML::Value << m.p_std_m.x();
    out << YAML::Key << "std_y" << YAML::Value << m.p_std_m.y();
    out << YAML::Key << "std_z" << YAML::Value << m.p_std_m.z();
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  VRREG_THROW_UNLESS(out.good(), "export: YAML emitter: " << out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

std::string urdf_text(const RegistrationModel& model, const RigidTransform& T) {
  const Eigen::Vector3d rpy = kinematics::rpy_from_rotation(T.rotation);
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n";
  out << "<!-- vrreg export: " << kTransformDirection << " -->\n";
  out << "<!-- origin: xyz in metres, rpy in radians (R = Rz(yaw) Ry(pitch) Rx(roll)). Paste the "
         "joint into the cell's URDF; robot_base is the robot's base link. -->\n";
  out << "<robot name=\"vrreg_registration\">\n";
  out << "  <link name=\"robot_base\"/>\n";
  out << "  <link name=\"sensor\"/>\n";
  out << "  <joint name=\"robot_base_to_sensor\" type=\"fixed\">\n";
  out << "    <parent link=\"robot_base\"/>\n";
  out << "    <child link=\"sensor\"/>\n";
  out << "    <origin xyz=\"" << number(T.translation_m.x()) << " " << number(T.translation_m.y())
      << " " << number(T.translation_m.z()) << "\" rpy=\"" << number(rpy.x()) << " "
      << number(rpy.y()) << " " << number(rpy.z()) << "\"/>\n";
  out << "  </joint>\n";
  out << "</robot>\n";
  if (model.marker_offset) {
    const Eigen::Vector3d& p = model.marker_offset->p_flange_marker_m;
    out << "<!-- Marker offset: " << kMarkerDirection << ". As a joint of the robot's URDF "
        << "(replace 'flange' with its flange link):\n";
    out << "  <link name=\"marker\"/>\n";
    out << "  <joint name=\"flange_to_marker\" type=\"fixed\">\n";
    out << "    <parent link=\"flange\"/>\n";
    out << "    <child link=\"marker\"/>\n";
    out << "    <origin xyz=\"" << number(p.x()) << " " << number(p.y()) << " " << number(p.z())
        << "\" rpy=\"0 0 0\"/>\n";
    out << "  </joint>\n";
    out << "-->\n";
  }
  return out.str();
}

std::string json_text(const RegistrationModel& model, const RigidTransform& T) {
  nlohmann::ordered_json out;
  out["format"] = "vrreg-transform";
  out["direction"] = kTransformDirection;
  out["units"] = {{"length", "m"}};
  const Eigen::Matrix4d m = T.isometry().matrix();
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  out["T_robot_sensor"] = rows;
  const Eigen::Quaterniond q = quaternion(T);
  out["xyz_m"] = {T.translation_m.x(), T.translation_m.y(), T.translation_m.z()};
  out["quaternion_xyzw"] = {q.x(), q.y(), q.z(), q.w()};
  if (model.marker_offset) {
    const MarkerOffsetModel& mo = *model.marker_offset;
    out["marker_offset"] = {
        {"direction", kMarkerDirection},
        {"p_flange_marker_m",
         {mo.p_flange_marker_m.x(), mo.p_flange_marker_m.y(), mo.p_flange_marker_m.z()}},
        {"p_std_m", {mo.p_std_m.x(), mo.p_std_m.y(), mo.p_std_m.z()}}};
  }
  return out.dump(2) + "\n";
}

}  // namespace

const char* const kTransformDirection =
    "T_robot_sensor maps points measured in the sensor (tracker) frame into the robot base frame, "
    "p_robot = R p_sensor + t; it is the pose of the sensor frame in the robot base frame (parent "
    "robot_base, child sensor)";

ExportFormat parse_export_format(const std::string& text) {
  if (text == "yaml") return ExportFormat::kYaml;
  if (text == "urdf") return ExportFormat::kUrdf;
  if (text == "json") return ExportFormat::kJson;
  VRREG_THROW_UNLESS(false, "unknown export format '" << text << "' (yaml, urdf or json)");
  return ExportFormat::kJson;  // not reached
}

std::string export_model(const RegistrationModel& model, ExportFormat format) {
  model.validate();
  VRREG_THROW_UNLESS(model.T_robot_sensor.scale == 1.0,
                     "export: the model has a scale (" << model.T_robot_sensor.scale
                                                       << "): a similarity, not a rigid transform; "
                                                          "register without `scale`");
  const RigidTransform T = model.T_robot_sensor.rigid();
  switch (format) {
    case ExportFormat::kYaml:
      return yaml_text(model, T);
    case ExportFormat::kUrdf:
      return urdf_text(model, T);
    case ExportFormat::kJson:
      return json_text(model, T);
  }
  return {};
}

}  // namespace vrreg::io
