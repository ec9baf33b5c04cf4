// SPDX-License-Identifier: Apache-2.0
// The model file: exact round trip, and a clear error for every kind of broken file.
#include "vrreg/io/model_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "io_test_helpers.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;
using json = nlohmann::ordered_json;

RegistrationModel random_model(Random& rng, int n_fiducials) {
  RegistrationModel m;
  m.T_robot_sensor = vrreg::testing::random_transform(rng, 2.0);
  m.fre_m = rng.uniform(0, 1e-3);
  m.sigma_l_m = rng.uniform(0, 1e-3);
  m.config = 3;
  m.source = "fiducials \xC3\xA4.csv";
  m.interpolation.method = InterpolationMethod::kOctuplet;
  m.interpolation.cube_edge_m = 0.0337;
  m.interpolation.match_tolerance_m = 2.5e-6;
  m.corrections_sensor_m = Points3(3, n_fiducials);
  for (int j = 0; j < n_fiducials; ++j) {
    Location f;
    f.point = "F" + std::to_string(j);
    if (j % 2 == 0) f.config = j;
    f.robot_m = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    f.sensor_m = Eigen::Vector3d(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3));
    f.n_readings = 12;
    f.sensor_sq_dev_m2 = Eigen::Vector3d(rng.uniform(0, 1e-8), rng.uniform(0, 1e-8), 0.0);
    if (j % 3 != 0) f.q_rad = {rng.uniform(-6, 6), rng.uniform(-6, 6), -0.0, 1e-300};
    m.fiducials.push_back(f);
    m.corrections_sensor_m.col(j) = rng.normal3(1e-4);
  }
  return m;
}

// |a - b| <= 1e-15 |b| per coefficient (unit conversion costs at most an ulp or two).
::testing::AssertionResult relative_equal(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    if (std::abs(a(i) - b(i)) > 1e-15 * std::abs(b(i))) {
      return ::testing::AssertionFailure() << "coefficient " << i << ": " << a(i) << " vs " << b(i);
    }
  }
  return ::testing::AssertionSuccess();
}

/// The same model as a version 1 file would hold it: lengths in millimetres, no corrector.
json as_version_1(json doc) {
  const auto mm = [](json& object, const std::string& key, double factor = 1e3) {
    if (!object.contains(key + "_m" + (factor == 1e6 ? "2" : ""))) return;
    const std::string from = key + (factor == 1e6 ? "_m2" : "_m");
    const std::string to = key + (factor == 1e6 ? "_mm2" : "_mm");
    json value = object[from];
    if (value.is_array()) {
      for (auto& v : value) v = v.get<double>() * factor;
    } else {
      value = value.get<double>() * factor;
    }
    object.erase(from);
    object[to] = value;
  };
  doc["version"] = 1;
  doc["units"]["length"] = "mm";
  for (const char* key : {"translation", "fre", "sigma_l", "sigma_rep"}) mm(doc, key);
  mm(doc["interpolation"], "cube");
  mm(doc["interpolation"], "match_tolerance");
  if (doc.contains("sigma_l_sampling")) mm(doc["sigma_l_sampling"], "interval");
  if (doc.contains("marker_offset")) {
    mm(doc["marker_offset"], "p_flange_marker");
    mm(doc["marker_offset"], "p_std");
  }
  for (auto& f : doc["fiducials"]) {
    for (const char* key : {"robot", "sensor", "correction"}) mm(f, key);
    mm(f, "sensor_sq_dev", 1e6);
  }
  doc.erase("corrector");
  return doc;
}

// Version 2 stores metres: every number reads back to the bit, and a model saved again is the
// same text (version 1's millimetres lost an ulp on ~15 % of the values, and drifted).
TEST(ModelJson, RoundTripIsExactToTheBit) {
  Random rng(17);
  const RegistrationModel m = random_model(rng, 9);
  const std::string text = format_model_json(m);
  const RegistrationModel r = parse_model_json(text, "model.json");
  EXPECT_EQ(r.T_robot_sensor.translation_m, m.T_robot_sensor.translation_m);
  EXPECT_EQ(r.fre_m, m.fre_m);
  EXPECT_EQ(r.sigma_l_m, m.sigma_l_m);
  EXPECT_EQ(r.interpolation.cube_edge_m, m.interpolation.cube_edge_m);
  EXPECT_EQ(r.interpolation.match_tolerance_m, m.interpolation.match_tolerance_m);
  EXPECT_EQ(r.corrections_sensor_m, m.corrections_sensor_m);
  for (std::size_t j = 0; j < m.fiducials.size(); ++j) {
    EXPECT_EQ(r.fiducials[j].robot_m, m.fiducials[j].robot_m);
    EXPECT_EQ(r.fiducials[j].sensor_m, m.fiducials[j].sensor_m);
    EXPECT_EQ(r.fiducials[j].sensor_sq_dev_m2, m.fiducials[j].sensor_sq_dev_m2);
  }
  EXPECT_EQ(format_model_json(r), text);
}

// Version 1 files (millimetres) are read as they always were: each length divided by 1000.
TEST(ModelJson, Version1FilesAreStillRead) {
  Random rng(19);
  const RegistrationModel m = random_model(rng, 5);
  const json v1 = as_version_1(json::parse(format_model_json(m)));
  const RegistrationModel r = parse_model_json(v1.dump(), "old.json");
  for (std::size_t j = 0; j < m.fiducials.size(); ++j) {
    EXPECT_EQ(r.fiducials[j].robot_m,
              (Eigen::Vector3d(v1["fiducials"][j]["robot_mm"][0].get<double>(),
                               v1["fiducials"][j]["robot_mm"][1].get<double>(),
                               v1["fiducials"][j]["robot_mm"][2].get<double>()) /
               1000.0)
                  .eval());
  }
  EXPECT_TRUE(relative_equal(r.corrections_sensor_m, m.corrections_sensor_m));
  EXPECT_EQ(r.interpolation.method, m.interpolation.method);
}

TEST(ModelJson, RoundTripIsExactToTheUlp) {
  Random rng(17);
  const RegistrationModel m = random_model(rng, 9);
  const RegistrationModel r = parse_model_json(format_model_json(m), "model.json");
  EXPECT_TRUE(relative_equal(r.T_robot_sensor.rotation, m.T_robot_sensor.rotation));
  EXPECT_EQ(r.T_robot_sensor.rotation, m.T_robot_sensor.rotation);  // no conversion: exact
  EXPECT_TRUE(relative_equal(r.T_robot_sensor.translation_m, m.T_robot_sensor.translation_m));
  EXPECT_EQ(r.T_robot_sensor.scale, m.T_robot_sensor.scale);
  EXPECT_TRUE(
      relative_equal(Eigen::Vector2d(r.fre_m, r.sigma_l_m), Eigen::Vector2d(m.fre_m, m.sigma_l_m)));
  EXPECT_EQ(r.config, m.config);
  EXPECT_EQ(r.source, m.source);
  EXPECT_EQ(r.interpolation.method, m.interpolation.method);
  EXPECT_TRUE(relative_equal(
      Eigen::Vector2d(r.interpolation.cube_edge_m, r.interpolation.match_tolerance_m),
      Eigen::Vector2d(m.interpolation.cube_edge_m, m.interpolation.match_tolerance_m)));
  ASSERT_EQ(r.fiducials.size(), m.fiducials.size());
  EXPECT_TRUE(relative_equal(r.corrections_sensor_m, m.corrections_sensor_m));
  for (std::size_t j = 0; j < m.fiducials.size(); ++j) {
    const Location& a = r.fiducials[j];
    const Location& b = m.fiducials[j];
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.config, b.config);
    EXPECT_EQ(a.role, Role::kFiducial);
    EXPECT_TRUE(a.has_robot);
    EXPECT_TRUE(relative_equal(a.robot_m, b.robot_m));
    EXPECT_TRUE(relative_equal(a.sensor_m, b.sensor_m));
    EXPECT_TRUE(relative_equal(a.sensor_sq_dev_m2, b.sensor_sq_dev_m2));
    EXPECT_EQ(a.n_readings, b.n_readings);
    EXPECT_EQ(a.q_rad, b.q_rad);  // radians are stored as is: exact
  }
}

TEST(ModelJson, LayoutStartsWithFormatAndVersion) {
  Random rng(1);
  RegistrationModel m = random_model(rng, 3);
  m.config.reset();
  const std::string text = format_model_json(m);
  const json doc = json::parse(text);
  EXPECT_EQ(doc.begin().key(), "format");
  EXPECT_EQ(doc["format"], "vrreg-model");
  EXPECT_EQ(doc["version"], 2);
  EXPECT_EQ(doc["units"]["length"], "m");
  EXPECT_EQ(doc["units"]["angle"], "rad");
  EXPECT_TRUE(doc["config"].is_null());
  EXPECT_EQ(doc["interpolation"]["method"], "octuplet");
  EXPECT_FALSE(doc["fiducials"][0].contains("q_rad"));  // omitted when empty
  EXPECT_TRUE(doc["fiducials"][1].contains("q_rad"));
  EXPECT_TRUE(doc["fiducials"][1]["config"].is_null());
  EXPECT_EQ(text.back(), '\n');
}

// Files written before the field models said "auto" for what is now "linear" (grid, else
// scattered): they keep their meaning; `auto` (cross-validation) is never stored, its choice is.
TEST(ModelJson, LegacyAutoReadsAsLinearAndFieldModelsRoundTrip) {
  Random rng(23);
  RegistrationModel m = random_model(rng, 4);
  json doc = json::parse(format_model_json(m));
  doc["interpolation"]["method"] = "auto";
  EXPECT_EQ(parse_model_json(doc.dump(), "new.json").interpolation.method,
            InterpolationMethod::kAuto);
  EXPECT_EQ(parse_model_json(as_version_1(doc).dump(), "old.json").interpolation.method,
            InterpolationMethod::kLinear);
  for (const auto method : {InterpolationMethod::kTrilinear, InterpolationMethod::kKriging,
                            InterpolationMethod::kRbf}) {
    m.interpolation.method = method;
    EXPECT_EQ(parse_model_json(format_model_json(m), "m.json").interpolation.method, method);
  }
  // The joint-space model's robot, tool (the marker) included, is kept exactly.
  m.interpolation.method = InterpolationMethod::kJoint;
  m.robot = kinematics::ur5().with_tool(Eigen::Isometry3d(Eigen::Translation3d(0.01, -0.02, 0.03)));
  for (Location& f : m.fiducials) f.q_rad = {0.1, -0.2, 0.3, -0.4, 0.5, -0.6};
  const RegistrationModel r = parse_model_json(format_model_json(m), "m.json");
  EXPECT_EQ(r.interpolation.method, InterpolationMethod::kJoint);
  ASSERT_TRUE(r.robot);
  EXPECT_EQ(r.robot->name(), m.robot->name());
  EXPECT_EQ(r.robot->T_flange_tcp().matrix(), m.robot->T_flange_tcp().matrix());
  EXPECT_EQ(r.robot->T_base_dh0().matrix(), m.robot->T_base_dh0().matrix());
  ASSERT_EQ(r.robot->n_joints(), 6);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(r.robot->row(i).d_m, m.robot->row(i).d_m);
}

TEST(ModelJson, WriteAndReadFile) {
  TempDir dir;
  Random rng(2);
  const RegistrationModel m = random_model(rng, 4);
  const std::string path = dir.file("model.json");
  write_model_json(path, m);
  const RegistrationModel r = read_model_json(path);
  EXPECT_EQ(r.fiducials.size(), 4u);
  EXPECT_EQ(r.T_robot_sensor.rotation, m.T_robot_sensor.rotation);
}

TEST(ModelJson, FormatRejectsModelsThatCannotBeReadBack) {
  Random rng(4);
  RegistrationModel m = random_model(rng, 4);
  m.corrections_sensor_m = Points3(3, 3);
  EXPECT_THROW((void)format_model_json(m), InputError);
  m = random_model(rng, 4);
  m.fre_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)format_model_json(m), InputError);
  m = random_model(rng, 4);
  m.fiducials[1].point = "bad\xff";
  EXPECT_THROW((void)format_model_json(m), InputError);
  // A joint-space model without its robot, or without every fiducial's joints.
  m = random_model(rng, 4);
  m.interpolation.method = InterpolationMethod::kJoint;
  EXPECT_THROW((void)format_model_json(m), InputError);
  m.robot = kinematics::ur5();
  for (Location& f : m.fiducials) f.q_rad.assign(6, 0.25);
  EXPECT_NO_THROW((void)format_model_json(m));
  m.fiducials[2].q_rad.pop_back();
  EXPECT_THROW((void)format_model_json(m), InputError);
}

// Broken model files: each one a FileError naming the file (and the line for JSON syntax).
class BrokenModel : public ::testing::Test {
 protected:
  void SetUp() override {
    Random rng(9);
    text_ = format_model_json(random_model(rng, 3));
    doc_ = json::parse(text_);
  }
  ::testing::AssertionResult fails(const std::string& text, std::size_t line,
                                   const std::string& fragment) {
    const std::string path = dir_.write("model.json", text);
    return throws_file_error([&] { (void)read_model_json(path); }, path, line, fragment);
  }
  ::testing::AssertionResult fails(const json& doc, const std::string& fragment) {
    return fails(doc.dump(2), 0, fragment);
  }
  TempDir dir_;
  std::string text_;
  json doc_;
};

TEST_F(BrokenModel, Truncated) {
  const std::string cut = text_.substr(0, text_.size() / 2);
  const std::size_t lines = static_cast<std::size_t>(std::count(cut.begin(), cut.end(), '\n'));
  EXPECT_TRUE(fails(cut, lines + 1, "invalid JSON (truncated or corrupted model file)"));
}
TEST_F(BrokenModel, CorruptedByte) {
  std::string bad = text_;
  const std::size_t at = bad.find("\"scale\"");
  bad[at] = '?';
  const std::size_t line =
      1 + static_cast<std::size_t>(
              std::count(bad.begin(), bad.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  EXPECT_TRUE(fails(bad, line, "invalid JSON"));
}
TEST_F(BrokenModel, EmptyFile) { EXPECT_TRUE(fails("", 0, "empty file")); }
TEST_F(BrokenModel, BinaryGarbage) {
  EXPECT_TRUE(fails(std::string("\x7f"
                                "ELF\0\0\x01\x02",
                                8),
                    1, "invalid JSON"));
}
TEST_F(BrokenModel, MissingFile) {
  const std::string path = dir_.file("nope.json");
  EXPECT_TRUE(throws_file_error([&] { (void)read_model_json(path); }, path, 0, "cannot open"));
}
TEST_F(BrokenModel, NotAnObject) { EXPECT_TRUE(fails("[1, 2]", 0, "expected an object")); }
TEST_F(BrokenModel, WrongFormat) {
  doc_["format"] = "something-else";
  EXPECT_TRUE(fails(doc_, "not a vrreg model file"));
}
TEST_F(BrokenModel, UnknownVersion) {
  doc_["version"] = 7;
  EXPECT_TRUE(fails(doc_, "unsupported model version 7; this vrreg reads versions 1 to 2"));
}
TEST_F(BrokenModel, VersionAsString) {
  doc_["version"] = "1";
  EXPECT_TRUE(fails(doc_, "unsupported model version \"1\""));
}
TEST_F(BrokenModel, MissingVersion) {
  doc_.erase("version");
  EXPECT_TRUE(fails(doc_, "'version': missing key"));
}
TEST_F(BrokenModel, WrongUnits) {
  doc_["units"]["length"] = "mm";
  EXPECT_TRUE(fails(doc_, "'units.length': expected \"m\""));
}
TEST_F(BrokenModel, MissingKey) {
  doc_.erase("translation_m");
  EXPECT_TRUE(fails(doc_, "'translation_m': missing key"));
}
TEST_F(BrokenModel, IllTypedKey) {
  doc_["rotation"][1][2] = "zero";
  EXPECT_TRUE(fails(doc_, "'rotation[1][2]': expected a number, found string"));
}
TEST_F(BrokenModel, WrongArrayLength) {
  doc_["fiducials"][2]["robot_m"] = {1.0, 2.0};
  EXPECT_TRUE(fails(doc_, "'fiducials[2].robot_m': expected 3 numbers, found 2"));
}
TEST_F(BrokenModel, NonFiniteNumberAsNull) {
  doc_["fre_m"] = nullptr;  // what a NaN becomes in JSON
  EXPECT_TRUE(fails(doc_, "'fre_m': expected a number, found null"));
}
TEST_F(BrokenModel, OverflowingNumber) {
  std::string bad = text_;
  const std::size_t at = bad.find("\"scale\": ") + 9;
  bad.replace(at, bad.find(',', at) - at, "1e999");
  EXPECT_TRUE(fails(bad, 0, "invalid JSON"));
}
TEST_F(BrokenModel, RotationNotOrthonormal) {
  doc_["rotation"][0][0] = doc_["rotation"][0][0].get<double>() + 1e-6;
  EXPECT_TRUE(fails(doc_, "'rotation': not a proper rotation"));
}
TEST_F(BrokenModel, RotationIsAReflection) {
  for (auto& value : doc_["rotation"][2]) value = -value.get<double>();
  EXPECT_TRUE(fails(doc_, "'rotation': not a proper rotation"));
}
TEST_F(BrokenModel, NegativeScale) {
  doc_["scale"] = -1.0;
  EXPECT_TRUE(fails(doc_, "'scale': must be positive"));
}
TEST_F(BrokenModel, UnknownInterpolation) {
  doc_["interpolation"]["method"] = "cubic";
  EXPECT_TRUE(fails(doc_, "'interpolation.method': unknown interpolation method 'cubic'"));
}
TEST_F(BrokenModel, FiducialWithoutCorrection) {
  doc_["fiducials"][1].erase("correction_m");
  EXPECT_TRUE(fails(doc_, "'fiducials[1].correction_m': missing key"));
}
TEST_F(BrokenModel, NonIntegerReadings) {
  doc_["fiducials"][0]["n_readings"] = 2.5;
  EXPECT_TRUE(fails(doc_, "'fiducials[0].n_readings': expected an integer, found 2.5"));
}
TEST_F(BrokenModel, FiducialsNotAnArray) {
  doc_["fiducials"] = {{"a", 1}};
  EXPECT_TRUE(fails(doc_, "'fiducials': expected an array"));
}

}  // namespace
}  // namespace vrreg::io
