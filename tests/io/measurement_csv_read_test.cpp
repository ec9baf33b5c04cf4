// SPDX-License-Identifier: Apache-2.0
// Accepted measurement CSV variants and the averaging of repeat readings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "io_test_helpers.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg_test.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;

const std::string kHeader =
    "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n";

MeasurementSet parse(const std::string& text, const CsvReadOptions& options = {}) {
  std::istringstream in(text);
  return parse_measurement_csv(in, "test.csv", options);
}

TEST(ReadCsv, PlainFileInMillimetres) {
  const MeasurementSet set =
      parse(kHeader + "A,fiducial,100,200,300,1,2,3\nB,target,-1.5,0,2e3,4,5,6\n");
  EXPECT_EQ(set.source, "test.csv");
  ASSERT_EQ(set.locations.size(), 2u);
  const Location& a = set.locations[0];
  EXPECT_EQ(a.point, "A");
  EXPECT_EQ(a.role, Role::kFiducial);
  EXPECT_TRUE(a.has_robot);
  EXPECT_FALSE(a.config.has_value());
  EXPECT_EQ(a.n_readings, 1);
  EXPECT_EQ(a.source_line, 2u);
  EXPECT_EIGEN_NEAR(a.robot_m, Eigen::Vector3d(0.1, 0.2, 0.3), 0.0);
  EXPECT_EIGEN_NEAR(a.sensor_m, Eigen::Vector3d(0.001, 0.002, 0.003), 0.0);
  EXPECT_EIGEN_NEAR(a.sensor_sq_dev_m2, Eigen::Vector3d::Zero(), 0.0);
  const Location& b = set.locations[1];
  EXPECT_EQ(b.role, Role::kTarget);
  EXPECT_EQ(b.source_line, 3u);
  EXPECT_EIGEN_NEAR(b.robot_m, Eigen::Vector3d(-0.0015, 0.0, 2.0), 0.0);
  EXPECT_EQ(set.n_joints, 0);
  EXPECT_FALSE(set.has_config);
  EXPECT_FALSE(set.has_repeat);
}

TEST(ReadCsv, MetreColumns) {
  const MeasurementSet set = parse(
      "point,role,robot_x_m,robot_y_m,robot_z_m,sensor_x_m,sensor_y_m,sensor_z_m\n"
      "A,fiducial,0.1,0.2,0.3,1,2,3\n");
  EXPECT_EIGEN_NEAR(set.locations[0].robot_m, Eigen::Vector3d(0.1, 0.2, 0.3), 0.0);
  EXPECT_EIGEN_NEAR(set.locations[0].sensor_m, Eigen::Vector3d(1, 2, 3), 0.0);
}

TEST(ReadCsv, RadianAndDegreeJoints) {
  const std::string head = kHeader.substr(0, kHeader.size() - 1);
  const MeasurementSet rad =
      parse(head + ",q1_rad,q2_rad,q3_rad\nA,fiducial,1,2,3,4,5,6,0.5,-1,3\n");
  EXPECT_EQ(rad.n_joints, 3);
  EXPECT_EQ(rad.locations[0].q_rad, (std::vector<double>{0.5, -1.0, 3.0}));
  const MeasurementSet deg = parse(head + ",q2_deg,q1_deg\nA,fiducial,1,2,3,4,5,6,90,-180\n");
  EXPECT_EQ(deg.n_joints, 2);
  ASSERT_EQ(deg.locations[0].q_rad.size(), 2u);
  EXPECT_DOUBLE_EQ(deg.locations[0].q_rad[0], -std::numbers::pi);
  EXPECT_DOUBLE_EQ(deg.locations[0].q_rad[1], std::numbers::pi / 2);
}

TEST(ReadCsv, ColumnsInAnyOrderAndAnyCase) {
  const MeasurementSet set = parse(
      "repeat,Sensor_Z_MM,q1_rad,sensor_y_mm,CONFIG,sensor_x_mm,robot_z_mm,robot_y_mm,robot_x_mm,"
      "role,Point\n"
      "0,6,0.25,5,3,4,3,2,1,TARGET,P7\n");
  ASSERT_EQ(set.locations.size(), 1u);
  const Location& loc = set.locations[0];
  EXPECT_EQ(loc.point, "P7");
  EXPECT_EQ(loc.role, Role::kTarget);
  EXPECT_EQ(loc.config, 3);
  EXPECT_EQ(loc.q_rad, std::vector<double>{0.25});
  EXPECT_EIGEN_NEAR(loc.robot_m, Eigen::Vector3d(1, 2, 3) * 1e-3, 1e-18);
  EXPECT_EIGEN_NEAR(loc.sensor_m, Eigen::Vector3d(4, 5, 6) * 1e-3, 1e-18);
  EXPECT_TRUE(set.has_config);
  EXPECT_TRUE(set.has_repeat);
}

TEST(ReadCsv, CrlfBomCommentsBlankLinesAndNoFinalNewline) {
  const std::string text = "\xEF\xBB\xBF# exported by a tracker\r\n\r\n  # indented comment\r\n" +
                           std::string(
                               "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,"
                               "sensor_y_mm,sensor_z_mm\r\n") +
                           "# between rows\r\nA,fiducial,1,2,3,4,5,6\r\n,,,,,,,\r\n\r\n"
                           "B,fiducial,1,2,3,4,5,7";
  const MeasurementSet set = parse(text);
  ASSERT_EQ(set.locations.size(), 2u);
  EXPECT_EQ(set.locations[0].source_line, 6u);
  EXPECT_EQ(set.locations[1].point, "B");
  EXPECT_EQ(set.locations[1].source_line, 9u);
  EXPECT_DOUBLE_EQ(set.locations[1].sensor_m.z(), 0.007);
}

TEST(ReadCsv, BomBeforeHeader) {
  const MeasurementSet set = parse("\xEF\xBB\xBF" + kHeader + "A,fiducial,1,2,3,4,5,6\n");
  EXPECT_EQ(set.locations.size(), 1u);
}

TEST(ReadCsv, SpacesAroundFieldsAndPlusSigns) {
  const MeasurementSet set = parse(kHeader + "  A b ,\tfiducial , +1, 2 ,3,4,5,+6e0\n");
  EXPECT_EQ(set.locations[0].point, "A b");
  EXPECT_DOUBLE_EQ(set.locations[0].robot_m.x(), 0.001);
  EXPECT_DOUBLE_EQ(set.locations[0].sensor_m.z(), 0.006);
}

TEST(ReadCsv, Utf8Labels) {
  const MeasurementSet set = parse(kHeader + "Bohrung-\xC3\xA4,fiducial,1,2,3,4,5,6\n");
  EXPECT_EQ(set.locations[0].point, "Bohrung-\xC3\xA4");
}

TEST(ReadCsv, SensorOnlyPointsWhenRobotNotRequired) {
  CsvReadOptions options;
  options.require_robot = false;
  const MeasurementSet set =
      parse("point,role,sensor_x_mm,sensor_y_mm,sensor_z_mm\nA,target,1,2,3\n", options);
  ASSERT_EQ(set.locations.size(), 1u);
  EXPECT_FALSE(set.locations[0].has_robot);
  EXPECT_EIGEN_NEAR(set.locations[0].sensor_m, Eigen::Vector3d(1, 2, 3) * 1e-3, 1e-18);
  // A file with robot columns still fills them.
  const MeasurementSet full = parse(kHeader + "A,target,1,2,3,4,5,6\n", options);
  EXPECT_TRUE(full.locations[0].has_robot);
}

TEST(ReadCsv, RepeatsAreAveragedWithPerAxisSumOfSquaredDeviations) {
  Random rng(11);
  const int k = 12;
  const std::vector<std::string> points = {"F1", "F2", "F3"};
  std::vector<std::vector<Eigen::Vector3d>> readings(points.size());
  std::ostringstream text;
  text.precision(17);
  text << kHeader.substr(0, kHeader.size() - 1) << ",repeat\n";
  for (int r = 0; r < k; ++r) {  // interleaved: F1 F2 F3 F1 F2 F3 ...
    for (std::size_t p = 0; p < points.size(); ++p) {
      const Eigen::Vector3d x(100.0 * static_cast<double>(p) + rng.normal(0.05),
                              -20.0 + rng.normal(0.1), 1500.0 + rng.normal(0.02));
      readings[p].push_back(x);
      text << points[p] << ",fiducial,10,20," << p << "," << x.x() << "," << x.y() << "," << x.z()
           << "," << r << "\n";
    }
  }
  const MeasurementSet set = parse(text.str());
  ASSERT_EQ(set.locations.size(), points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Location& loc = set.locations[p];
    EXPECT_EQ(loc.point, points[p]);  // order of first appearance
    EXPECT_EQ(loc.source_line, p + 2);
    EXPECT_EQ(loc.n_readings, k);
    // Two-pass reference, in mm, then converted.
    Eigen::Vector3d mean_mm = Eigen::Vector3d::Zero();
    for (const auto& x : readings[p]) mean_mm += x;
    mean_mm /= k;
    Eigen::Vector3d ss_mm2 = Eigen::Vector3d::Zero();
    for (const auto& x : readings[p]) ss_mm2 += (x - mean_mm).cwiseAbs2();
    EXPECT_EIGEN_NEAR(loc.sensor_m, mean_mm * 1e-3, 1e-15);
    EXPECT_EIGEN_NEAR(loc.sensor_sq_dev_m2, ss_mm2 * 1e-6, 1e-18);
    EXPECT_GT(loc.sensor_sq_dev_m2.minCoeff(), 0.0);
  }
}

TEST(ReadCsv, SamePointInTwoConfigsIsTwoLocations) {
  const std::string head =
      "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,"
      "sensor_z_mm,config,q1_rad\n";
  const MeasurementSet set = parse(head +
                                   "A,fiducial,1,2,3,4,5,6,1,0.1\n"
                                   "A,fiducial,1,2,3,4,5,8,2,0.2\n"
                                   "B,fiducial,1,1,1,4,5,6,1,0.3\n"
                                   "A,fiducial,1,2,3,4,5,7,1,0.1\n");
  ASSERT_EQ(set.locations.size(), 3u);
  EXPECT_EQ(set.locations[0].config, 1);
  EXPECT_EQ(set.locations[0].n_readings, 2);
  EXPECT_DOUBLE_EQ(set.locations[0].sensor_m.z(), 0.0065);
  EXPECT_EQ(set.locations[1].config, 2);
  EXPECT_EQ(set.locations[1].q_rad, std::vector<double>{0.2});
  EXPECT_EQ(set.locations[2].point, "B");
  EXPECT_EQ(set.select(Role::kFiducial, 1), (std::vector<std::size_t>{0, 2}));
}

TEST(ReadCsv, RobotCoordinatesWithinToleranceAreTheSamePoint) {
  const MeasurementSet set =
      parse(kHeader + "A,fiducial,1,2,3,4,5,6\nA,fiducial,1.0000005,2,3,4,5,6\n");
  ASSERT_EQ(set.locations.size(), 1u);
  EXPECT_EQ(set.locations[0].n_readings, 2);
}

TEST(ReadCsv, ReadsFromDiskWithPathAsSource) {
  TempDir dir;
  const std::string path = dir.write("m.csv", kHeader + "A,fiducial,1,2,3,4,5,6\n");
  const MeasurementSet set = read_measurement_csv(path);
  EXPECT_EQ(set.source, path);
  EXPECT_EQ(set.locations.size(), 1u);
}

TEST(ReadCsv, ManyRepeatsOfFewLocationsStream) {
  // 200 000 rows of 4 locations: the result holds 4 locations whatever the file size.
  const int rows = vrreg::testing::sanitized() ? 20000 : 200000;
  std::string text = kHeader;
  text.reserve(text.size() + static_cast<std::size_t>(rows) * 32);
  for (int i = 0; i < rows; ++i) {
    text += "P" + std::to_string(i % 4) + ",fiducial,1,2," + std::to_string(i % 4) + ",4,5," +
            std::to_string(i % 3) + "\n";
  }
  const MeasurementSet set = parse(text);
  ASSERT_EQ(set.locations.size(), 4u);
  EXPECT_EQ(set.locations[0].n_readings, rows / 4);
}

// Marker orientations (rigid-body trackers): four unitless columns, normalised, repeats averaged
// as rotations (q and -q alike).
TEST(ReadCsv, MarkerOrientationColumns) {
  const std::string header =
      "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm,"
      "repeat,sensor_qx,sensor_qy,sensor_qz,SENSOR_QW\n";
  const double c = std::cos(0.05);
  const double s = std::sin(0.05);
  // Repeats of A: rotations by +0.1 and -0.1 rad about z, the second written as -q; mean: identity.
  const std::string text = header + "A,fiducial,1,2,3,4,5,6,0,0,0," + std::to_string(s) + "," +
                           std::to_string(c) + "\n" + "A,fiducial,1,2,3,4,5,6,1,0,0," +
                           std::to_string(s) + "," + std::to_string(-c) + "\n" +
                           "B,target,1,2,3,4,5,6,0,0,0,0,1.0004\n";
  const MeasurementSet set = parse(text);
  ASSERT_EQ(set.locations.size(), 2u);
  ASSERT_TRUE(set.locations[0].q_sensor_marker.has_value());
  const Eigen::Quaterniond a = *set.locations[0].q_sensor_marker;
  EXPECT_NEAR(std::abs(a.w()), 1.0, 1e-12);
  EXPECT_NEAR(a.vec().norm(), 0.0, 1e-6);  // std::to_string keeps 6 decimals
  ASSERT_TRUE(set.locations[1].q_sensor_marker.has_value());
  EXPECT_NEAR(set.locations[1].q_sensor_marker->norm(), 1.0, 1e-15);
  EXPECT_FALSE(parse(kHeader + "A,fiducial,1,2,3,4,5,6\n").locations[0].q_sensor_marker);
}

TEST(ReadCsv, MarkerOrientationAverageOfManyRepeats) {
  // Readings scattered 1 mrad about a rotation, half of them written with the opposite sign.
  Random rng(5);
  const Eigen::Quaterniond truth(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 2, 3).normalized()));
  std::string text =
      "point,role,sensor_x_mm,sensor_y_mm,sensor_z_mm,sensor_qx,sensor_qy,sensor_qz,sensor_qw\n";
  char line[256];
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d e = rng.normal3(1e-3);
    Eigen::Quaterniond q = truth * Eigen::Quaterniond(Eigen::AngleAxisd(e.norm(), e.normalized()));
    if (k % 2 == 1) q.coeffs() = -q.coeffs();
    std::snprintf(line, sizeof line, "A,target,0,0,0,%.17g,%.17g,%.17g,%.17g\n", q.x(), q.y(),
                  q.z(), q.w());
    text += line;
  }
  CsvReadOptions options;
  options.require_robot = false;
  const Location a = parse(text, options).locations[0];
  ASSERT_TRUE(a.q_sensor_marker);
  // The mean of 200 readings of 1 mrad per axis: within ~4 x 1e-3 / sqrt(200) of the truth.
  EXPECT_LT(a.q_sensor_marker->angularDistance(truth), 3e-4);
  // Their spread: 200 x 3 axes x (1 mrad)^2, give or take sqrt(2 / 600) = 6 % (one sd).
  EXPECT_NEAR(a.orientation_sq_dev_rad2 / (200 * 3 * 1e-6), 1.0, 0.2);
}

TEST(ReadCsv, CommandedOrientationColumns) {
  const std::string header =
      "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm,repeat,"
      "sensor_qx,sensor_qy,sensor_qz,sensor_qw,robot_qx,robot_qy,robot_qz,robot_qw\n";
  const std::string text = header + "A,fiducial,1,2,3,4,5,6,0,0,0,0,1,0,0.6,0,0.8\n" +
                           "A,fiducial,1,2,3,4,5,6,1,0,0,0,1,0,0.6,0,0.8\n";
  const MeasurementSet set = parse(text);
  ASSERT_TRUE(set.locations[0].q_robot_marker.has_value());
  EXPECT_EQ(set.locations[0].q_robot_marker->coeffs(), Eigen::Vector4d(0, 0.6, 0, 0.8));
  EXPECT_EQ(set.locations[0].orientation_sq_dev_rad2, 0.0);
  // Repeats must agree on the commanded orientation; it needs the measured one; all four.
  const auto error_of = [](const std::string& t) {
    try {
      parse(t);
    } catch (const FileError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of(header + "A,fiducial,1,2,3,4,5,6,0,0,0,0,1,0,0.6,0,0.8\n" +
                     "A,fiducial,1,2,3,4,5,6,1,0,0,0,1,0.6,0,0,0.8\n")
                .find("test.csv:3: point 'A' has a commanded orientation (robot_q)"),
            std::string::npos);
  EXPECT_NE(
      error_of(kHeader.substr(0, kHeader.size() - 1) + ",robot_qx,robot_qy,robot_qz,robot_qw\n")
          .find("robot_qx..robot_qw without sensor_qx..sensor_qw"),
      std::string::npos);
  EXPECT_NE(error_of(header + "A,fiducial,1,2,3,4,5,6,0,0,0,0,1,0,0.6,0,0.9\n")
                .find("robot_qx..robot_qw: the quaternion's norm is"),
            std::string::npos);
}

}  // namespace
}  // namespace vrreg::io
