// SPDX-License-Identifier: Apache-2.0
// Error-model files of the simulated test beds: round trip, partial files over the defaults,
// YAML, and one-line errors naming the file, key (and line for YAML).
#include "vrreg/robot_io/error_model_file.hpp"

#include <gtest/gtest.h>

#include "io_test_helpers.hpp"
#include "vrreg_test.hpp"

namespace vrreg::io {
namespace {

using testing::TempDir;
using testing::throws_file_error;

void expect_same(const simulation::TestbedErrorModel& a, const simulation::TestbedErrorModel& b) {
  const auto near = [](double x, double y) { return std::abs(x - y) <= 1e-11 * std::abs(x); };
  const auto near_list = [&](const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!near(x[i], y[i])) return false;
    }
    return true;
  };
  EXPECT_TRUE(near(a.robot.joint_offset_sigma_rad, b.robot.joint_offset_sigma_rad));
  EXPECT_TRUE(near(a.robot.link_length_sigma_m, b.robot.link_length_sigma_m));
  EXPECT_TRUE(near(a.robot.link_offset_sigma_m, b.robot.link_offset_sigma_m));
  EXPECT_TRUE(near(a.robot.twist_sigma_rad, b.robot.twist_sigma_rad));
  EXPECT_TRUE(near_list(a.robot.transmission_amplitude_rad, b.robot.transmission_amplitude_rad));
  EXPECT_TRUE(near_list(a.robot.transmission_period_rad, b.robot.transmission_period_rad));
  EXPECT_TRUE(near(a.robot.repeatability_sigma_m, b.robot.repeatability_sigma_m));
  EXPECT_EQ(a.robot.compliance, b.robot.compliance);
  EXPECT_TRUE(near_list(a.robot.link_mass_kg, b.robot.link_mass_kg));
  EXPECT_TRUE(near_list(a.robot.joint_stiffness_nm_per_rad, b.robot.joint_stiffness_nm_per_rad));
  EXPECT_TRUE(near(a.robot.payload_kg, b.robot.payload_kg));
  EXPECT_TRUE(near_list(a.robot.lost_motion_rad, b.robot.lost_motion_rad));
  EXPECT_TRUE(near(a.robot.lost_motion_take_up, b.robot.lost_motion_take_up));
  EXPECT_TRUE(near(a.tracker.distance_m, b.tracker.distance_m));
  EXPECT_TRUE(near(a.tracker.azimuth_rad, b.tracker.azimuth_rad));
  EXPECT_TRUE(near(a.tracker.elevation_rad, b.tracker.elevation_rad));
  EXPECT_EIGEN_NEAR(a.tracker.noise_sigma_m, b.tracker.noise_sigma_m, 1e-15);
  EXPECT_EQ(a.tracker.readings_per_location, b.tracker.readings_per_location);
}

TEST(ErrorModelFile, RoundTripsEveryParameter) {
  TempDir dir;
  for (const simulation::Testbed& testbed :
       {simulation::ur5_testbed(), simulation::lwr4_testbed()}) {
    simulation::TestbedErrorModel model = testbed.default_errors;
    model.robot.compliance = true;
    model.robot.payload_kg = 0.37;
    model.tracker.noise_sigma_m = Eigen::Vector3d(0.05e-3, 0.06e-3, 0.09e-3);
    model.tracker.readings_per_location = 5;
    const std::string path = dir.file(testbed.name + ".json");
    write_error_model_file(path, model, testbed.name);
    const simulation::TestbedErrorModel back = read_error_model_file(path, testbed);
    expect_same(back, model);
    // Values are written to 12 significant digits; writing what was read gives the same file.
    EXPECT_EQ(format_error_model(back, testbed.name), testing::read_text(path));
  }
}

TEST(ErrorModelFile, RoundTripsLostMotionAndWritesNoKeyWithout) {
  const simulation::Testbed testbed = simulation::ur5_testbed();
  EXPECT_EQ(format_error_model(testbed.default_errors, testbed.name).find("lost_motion"),
            std::string::npos);
  const simulation::TestbedErrorModel model = parse_error_model(
      R"({"robot": {"lost_motion_arcmin": [0.6, 0.15, 0.15, 0.5, 0.4, 0.7],
                    "lost_motion_take_up": 0.8}})",
      "e.json", testbed);
  ASSERT_EQ(model.robot.lost_motion_rad.size(), 6u);
  EXPECT_NEAR(model.robot.lost_motion_rad[0], 0.6 / 60.0 * M_PI / 180.0, 1e-18);
  EXPECT_DOUBLE_EQ(model.robot.lost_motion_take_up, 0.8);
  const std::string text = format_error_model(model, testbed.name);
  EXPECT_NE(text.find("\"lost_motion_arcmin\""), std::string::npos);
  expect_same(parse_error_model(text, "back.json", testbed), model);
  EXPECT_TRUE(testing::throws_file_error(
      [&] {
        parse_error_model(R"({"robot": {"lost_motion_arcmin": [1, 1, 1, 1, 1, 1],
                                        "lost_motion_take_up": 2}})",
                          "t.json", testbed);
      },
      "t.json", 0, "take-up must be in [0, 1]"));
}

TEST(ErrorModelFile, AbsentKeysKeepTheDefaults) {
  const simulation::Testbed testbed = simulation::ur5_testbed();
  const simulation::TestbedErrorModel model = parse_error_model(
      R"({"robot": {"repeatability_sigma_mm": 0.02}, "tracker": {"readings_per_location": 3}})",
      "e.json", testbed);
  EXPECT_DOUBLE_EQ(model.robot.repeatability_sigma_m, 0.02e-3);
  EXPECT_EQ(model.tracker.readings_per_location, 3);
  simulation::TestbedErrorModel expected = testbed.default_errors;
  expected.robot.repeatability_sigma_m = 0.02e-3;
  expected.tracker.readings_per_location = 3;
  expect_same(model, expected);
}

TEST(ErrorModelFile, ReadsYaml) {
  const simulation::TestbedErrorModel model = parse_error_model(
      "robot:\n  joint_offset_sigma_deg: 0.5\n  transmission_amplitude_arcmin: []\n"
      "  transmission_period_deg: []\ntracker:\n  noise_sigma_mm: [0.01, 0.02, 0.03]\n",
      "e.yaml", simulation::ur5_testbed());
  EXPECT_NEAR(model.robot.joint_offset_sigma_rad, 0.5 * M_PI / 180, 1e-15);
  EXPECT_TRUE(model.robot.transmission_amplitude_rad.empty());
  EXPECT_EIGEN_NEAR(model.tracker.noise_sigma_m, Eigen::Vector3d(1e-5, 2e-5, 3e-5), 1e-18);
}

TEST(ErrorModelFile, BadContentNamesFileAndKey) {
  const simulation::Testbed ur5 = simulation::ur5_testbed();
  const auto parse = [&](const std::string& text, const std::string& name) {
    return [=] { parse_error_model(text, name, ur5); };
  };
  EXPECT_TRUE(throws_file_error(parse(R"({"robot": {"joint_offset_sigma": 1}})", "a.json"),
                                "a.json", 0, "robot.joint_offset_sigma: unknown key"));
  EXPECT_TRUE(
      throws_file_error(parse(R"({"robots": {}})", "b.json"), "b.json", 0, "robots: unknown key"));
  EXPECT_TRUE(throws_file_error(
      parse(R"({"robot": {"transmission_period_deg": [1, 2]}})", "c.json"), "c.json", 0,
      "robot.transmission_period_deg: expected a list of 6 numbers"));
  EXPECT_TRUE(throws_file_error(parse(R"({"testbed": "lwr4"})", "d.json"), "d.json", 0,
                                "for test bed \"lwr4\", not ur5"));
  EXPECT_TRUE(throws_file_error(parse(R"({"robot": {"repeatability_sigma_mm": -1}})", "e.json"),
                                "e.json", 0, "repeatability sigma must be finite and >= 0"));
  EXPECT_TRUE(throws_file_error(parse("robot:\n  payload_kg: heavy\n", "f.yaml"), "f.yaml", 2,
                                "robot.payload_kg: expected a number"));
  EXPECT_TRUE(throws_file_error(parse(R"({"tracker": {"readings_per_location": 0}})", "g.json"),
                                "g.json", 0, "readings_per_location: expected an integer"));
  EXPECT_TRUE(throws_file_error(parse("", "h.json"), "h.json", 0, "empty error-model file"));
  EXPECT_TRUE(throws_file_error([&] { read_error_model_file("/nonexistent/x.json", ur5); },
                                "/nonexistent/x.json", 0, "cannot open"));
}

}  // namespace
}  // namespace vrreg::io
