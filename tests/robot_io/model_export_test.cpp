// SPDX-License-Identifier: Apache-2.0
// vrreg export: every format parses back, with an independent reader, to the model's
// transform and marker offset, and says which way the transform goes.
#include "vrreg/robot_io/model_export.hpp"

#include <urdf_parser/urdf_parser.h>
#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

RegistrationModel model_with_offset() {
  Random rng(7);
  RegistrationModel model;
  model.T_robot_sensor = testing::random_transform(rng, 2.0);
  Location f;
  f.point = "F0";
  f.robot_m = Eigen::Vector3d(0.4, 0.1, 0.2);
  f.sensor_m = Eigen::Vector3d(1.0, 2.0, 3.0);
  f.n_readings = 1;
  model.fiducials = {f};
  model.corrections_sensor_m = Points3::Zero(3, 1);
  model.marker_offset = MarkerOffsetModel{Eigen::Vector3d(0.035, -0.025, 0.085),
                                          Eigen::Vector3d(4e-5, 5e-5, 6e-5), kinematics::ur5()};
  return model;
}

Eigen::Matrix3d rotation_of(double qx, double qy, double qz, double qw) {
  return Eigen::Quaterniond(qw, qx, qy, qz).normalized().toRotationMatrix();
}

TEST(ModelExport, YamlParsesBackToTheTransformAndOffset) {
  const RegistrationModel model = model_with_offset();
  const std::string text = io::export_model(model, io::ExportFormat::kYaml);
  const YAML::Node doc = YAML::Load(text);
  const YAML::Node t = doc["transformation"];
  const Eigen::Vector3d xyz(t["x"].as<double>(), t["y"].as<double>(), t["z"].as<double>());
  EXPECT_EIGEN_NEAR(xyz, model.T_robot_sensor.translation_m, 1e-15);
  EXPECT_EIGEN_NEAR(rotation_of(t["qx"].as<double>(), t["qy"].as<double>(), t["qz"].as<double>(),
                                t["qw"].as<double>()),
                    model.T_robot_sensor.rotation, 1e-14);
  EXPECT_FALSE(doc["eye_on_hand"].as<bool>());
  EXPECT_NE(doc["direction"].as<std::string>().find("sensor (tracker) frame into the robot base"),
            std::string::npos);
  const YAML::Node m = doc["marker_offset"];
  EXPECT_EIGEN_NEAR(Eigen::Vector3d(m["x"].as<double>(), m["y"].as<double>(), m["z"].as<double>()),
                    model.marker_offset->p_flange_marker_m, 1e-15);
  EXPECT_NEAR(m["std_z"].as<double>(), 6e-5, 1e-18);
}

TEST(ModelExport, UrdfParsesBackWithUrdfdom) {
  const RegistrationModel model = model_with_offset();
  const std::string text = io::export_model(model, io::ExportFormat::kUrdf);
  const urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(text);
  ASSERT_TRUE(urdf) << text;
  const urdf::JointConstSharedPtr joint = urdf->getJoint("robot_base_to_sensor");
  ASSERT_TRUE(joint);
  EXPECT_EQ(joint->parent_link_name, "robot_base");
  EXPECT_EQ(joint->child_link_name, "sensor");
  const urdf::Pose& pose = joint->parent_to_joint_origin_transform;
  EXPECT_EIGEN_NEAR(Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z),
                    model.T_robot_sensor.translation_m, 1e-15);
  double qx, qy, qz, qw;
  pose.rotation.getQuaternion(qx, qy, qz, qw);
  EXPECT_EIGEN_NEAR(rotation_of(qx, qy, qz, qw), model.T_robot_sensor.rotation, 1e-12);
  EXPECT_NE(text.find("p_robot = R p_sensor + t"), std::string::npos);
  EXPECT_NE(text.find("flange_to_marker"), std::string::npos);  // the offset, as a joint to paste
}

TEST(ModelExport, JsonHasTheMatrixAndTheOffset) {
  const RegistrationModel model = model_with_offset();
  const nlohmann::json j = nlohmann::json::parse(io::export_model(model, io::ExportFormat::kJson));
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = j["T_robot_sensor"][r][c].get<double>();
  }
  EXPECT_EIGEN_NEAR(m, model.T_robot_sensor.rigid().isometry().matrix(), 0.0);
  const auto p = j["marker_offset"]["p_flange_marker_m"].get<std::vector<double>>();
  EXPECT_EIGEN_NEAR(Eigen::Vector3d(p[0], p[1], p[2]), model.marker_offset->p_flange_marker_m, 0.0);
  EXPECT_NE(j["direction"].get<std::string>().find("parent robot_base, child sensor"),
            std::string::npos);
}

TEST(ModelExport, ScaledModelIsRefused) {
  RegistrationModel model = model_with_offset();
  model.T_robot_sensor.scale = 1.001;
  EXPECT_THROW(io::export_model(model, io::ExportFormat::kYaml), InputError);
  EXPECT_THROW(io::parse_export_format("xml"), InputError);
}

}  // namespace
}  // namespace vrreg
