// SPDX-License-Identifier: Apache-2.0
// Writing readings and reading them back gives the same averages.
#include "vrreg/io/measurement_csv_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "io_test_helpers.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg_test.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;

MeasurementSet parse_round_trip(const std::string& text, const CsvReadOptions& options = {}) {
  std::istringstream in(text);
  return parse_measurement_csv(in, "round-trip", options);
}

// K readings of each of n points in two configurations, visited point by point.
std::vector<Reading> simulated_readings(Random& rng, int n_points, int k) {
  std::vector<Reading> out;
  for (int p = 0; p < n_points; ++p) {
    const Eigen::Vector3d robot_m(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3),
                                  rng.uniform(0.1, 0.5));
    for (int config = 0; config < 2; ++config) {
      const std::vector<double> q = {rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3)};
      const Eigen::Vector3d sensor_m = robot_m + Eigen::Vector3d(1.2, -0.4, 2.1);
      for (int r = 0; r < k; ++r) {
        Reading reading;
        reading.point = "P" + std::to_string(p);
        reading.role = p % 3 == 0 ? Role::kTarget : Role::kFiducial;
        reading.robot_m = robot_m;
        reading.sensor_m = sensor_m + rng.normal3(5.8e-5);
        reading.config = config;
        reading.q_rad = q;
        reading.repeat = r;
        out.push_back(reading);
      }
    }
  }
  return out;
}

TEST(WriteCsv, RoundTripGivesTheSameAverages) {
  Random rng(5);
  const int k = 12;
  const std::vector<Reading> readings = simulated_readings(rng, 10, k);
  const MeasurementSet set = parse_round_trip(format_measurement_csv(readings, {"seed 5", "UR5"}));
  ASSERT_EQ(set.locations.size(), 20u);
  EXPECT_EQ(set.n_joints, 3);
  EXPECT_TRUE(set.has_config);
  EXPECT_TRUE(set.has_repeat);
  for (std::size_t i = 0; i < set.locations.size(); ++i) {
    const Location& loc = set.locations[i];
    const Reading& first = readings[i * k];
    EXPECT_EQ(loc.point, first.point);
    EXPECT_EQ(loc.role, first.role);
    EXPECT_EQ(loc.config, first.config);
    EXPECT_EQ(loc.n_readings, k);
    EXPECT_EIGEN_NEAR(loc.robot_m, first.robot_m, 1e-15);
    ASSERT_EQ(loc.q_rad.size(), 3u);
    for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(loc.q_rad[j], first.q_rad[j]);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int r = 0; r < k; ++r) mean += readings[i * k + r].sensor_m;
    mean /= k;
    Eigen::Vector3d ss = Eigen::Vector3d::Zero();
    for (int r = 0; r < k; ++r) ss += (readings[i * k + r].sensor_m - mean).cwiseAbs2();
    EXPECT_EIGEN_NEAR(loc.sensor_m, mean, 1e-15 * 3.0);
    // Each reading may move by an ulp (~2e-16 m) through mm text; against deviations of ~6e-5 m
    // that is ~1e-11 relative in the sums of squares.
    EXPECT_EIGEN_NEAR(loc.sensor_sq_dev_m2, ss, 1e-10 * ss.maxCoeff());
  }
}

TEST(WriteCsv, SingleValuesRoundTripToTheUlp) {
  Random rng(8);
  std::vector<Reading> readings;
  for (int i = 0; i < 500; ++i) {
    Reading r;
    r.point = "X" + std::to_string(i);
    r.robot_m = Eigen::Vector3d(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
    r.sensor_m = Eigen::Vector3d(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
    readings.push_back(r);
  }
  const MeasurementSet set = parse_round_trip(format_measurement_csv(readings));
  ASSERT_EQ(set.locations.size(), readings.size());
  for (std::size_t i = 0; i < readings.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(set.locations[i].robot_m(a), readings[i].robot_m(a),
                  2.0 * std::abs(readings[i].robot_m(a)) * 1.12e-16);
      EXPECT_NEAR(set.locations[i].sensor_m(a), readings[i].sensor_m(a),
                  2.0 * std::abs(readings[i].sensor_m(a)) * 1.12e-16);
    }
  }
}

TEST(WriteCsv, FormatIsMillimetresWithCommentsFirst) {
  Reading r;
  r.point = "A";
  r.robot_m = Eigen::Vector3d(0.1, -0.25, 1.0);
  r.sensor_m = Eigen::Vector3d(0.001, 0.002, 0.003);
  EXPECT_EQ(format_measurement_csv({r}, {"two\nlines"}),
            "# two\n# lines\n"
            "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n"
            "A,fiducial,100,-250,1000,1,2,3\n");
}

TEST(WriteCsv, SensorOnlyReadingsHaveNoRobotColumns) {
  Reading r;
  r.point = "T";
  r.role = Role::kTarget;
  r.has_robot = false;
  r.sensor_m = Eigen::Vector3d(0.5, 0.5, 0.5);
  const std::string text = format_measurement_csv({r});
  EXPECT_EQ(text.find("robot_"), std::string::npos);
  CsvReadOptions options;
  options.require_robot = false;
  const MeasurementSet set = parse_round_trip(text, options);
  EXPECT_FALSE(set.locations[0].has_robot);
}

TEST(WriteCsv, RejectsReadingsThatCannotBeReadBack) {
  Reading ok;
  ok.point = "A";
  const std::vector<std::string> labels = {"", "a,b", "#1", " A", "q\"x", "a\nb", "a\x01", "\xff"};
  for (const std::string& label : labels) {
    Reading bad = ok;
    bad.point = label;
    EXPECT_THROW((void)format_measurement_csv({ok, bad}), InputError) << label;
  }
  Reading with_config = ok;
  with_config.config = 1;
  EXPECT_THROW((void)format_measurement_csv({ok, with_config}), InputError);
  Reading with_joints = ok;
  with_joints.q_rad = {0.1};
  EXPECT_THROW((void)format_measurement_csv({ok, with_joints}), InputError);
  Reading nan = ok;
  nan.sensor_m.x() = std::nan("");
  EXPECT_THROW((void)format_measurement_csv({nan}), InputError);
  EXPECT_THROW((void)format_measurement_csv({}), InputError);
  EXPECT_THROW((void)format_measurement_csv({ok}, {"bad\x02"}), InputError);
}

TEST(WriteCsv, WritesFileThatReadsBack) {
  TempDir dir;
  Random rng(3);
  const std::vector<Reading> readings = simulated_readings(rng, 3, 2);
  const std::string path = dir.file("out.csv");
  write_measurement_csv(path, readings, {"comment"});
  const MeasurementSet set = read_measurement_csv(path);
  EXPECT_EQ(set.locations.size(), 6u);
}

TEST(WriteCsv, OrientationsRoundTripToTheBit) {
  Random rng(9);
  std::vector<Reading> readings(4);
  for (std::size_t p = 0; p < readings.size(); ++p) {
    readings[p].point = "P" + std::to_string(p);
    readings[p].sensor_m = rng.normal3(1.0);
    readings[p].q_sensor_marker = Eigen::Quaterniond(rng.rotation());
    readings[p].q_robot_marker = Eigen::Quaterniond(rng.rotation());
  }
  const std::string text = format_measurement_csv(readings);
  EXPECT_NE(
      text.find(",sensor_qx,sensor_qy,sensor_qz,sensor_qw,robot_qx,robot_qy,robot_qz,robot_qw\n"),
      std::string::npos);
  const MeasurementSet set = parse_round_trip(text);
  for (std::size_t p = 0; p < readings.size(); ++p) {
    // One reading each: read as written (the shortest text that reads back exactly).
    EXPECT_LT(
        (set.locations[p].q_sensor_marker->coeffs() - readings[p].q_sensor_marker->coeffs()).norm(),
        4e-16);
    EXPECT_LT(
        (set.locations[p].q_robot_marker->coeffs() - readings[p].q_robot_marker->coeffs()).norm(),
        4e-16);
  }
  // All readings or none; a commanded orientation needs the measured one.
  readings[1].q_robot_marker.reset();
  EXPECT_THROW(format_measurement_csv(readings), InputError);
  for (Reading& r : readings) r.q_sensor_marker.reset();
  readings[1].q_robot_marker = Eigen::Quaterniond::Identity();
  EXPECT_THROW(format_measurement_csv(readings), InputError);
}

}  // namespace
}  // namespace vrreg::io
