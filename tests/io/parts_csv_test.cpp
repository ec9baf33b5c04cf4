// SPDX-License-Identifier: Apache-2.0
// The parts file of `vrreg plan` (Procedure 1): what it accepts, and one FileError line naming
// file and line for every kind of bad input.
#include "vrreg/io/parts_csv.hpp"

#include <gtest/gtest.h>

#include "io_test_helpers.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

class PartsCsv : public ::testing::Test {
 protected:
  ::testing::AssertionResult fails(const std::string& content, std::size_t line,
                                   const std::string& fragment) {
    const std::string path = dir_.write("parts.csv", content);
    return throws_file_error([&] { (void)read_parts_csv(path); }, path, line, fragment);
  }
  std::vector<PartRecord> read(const std::string& content) {
    return read_parts_csv(dir_.write("parts.csv", content));
  }
  TempDir dir_;
};

TEST_F(PartsCsv, ReadsMillimetresWithCommentsBomAndCrlf) {
  const auto parts = read(
      "\xEF\xBB\xBF# housing features\r\nPoint,ROBOT_X_MM, robot_y_mm ,robot_z_mm\r\n"
      "hole_A,450,-100,250\r\n\r\n# another\r\nhole B , +460.5,-1e2,2.5e2");
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].point, "hole_A");
  EXPECT_EQ(parts[0].line, 3u);
  EXPECT_DOUBLE_EQ(parts[0].robot_m.x(), 0.45);
  EXPECT_DOUBLE_EQ(parts[0].robot_m.y(), -0.1);
  EXPECT_EQ(parts[1].point, "hole B");
  EXPECT_DOUBLE_EQ(parts[1].robot_m.x(), 0.4605);
}

TEST_F(PartsCsv, ReadsMetresInAnyColumnOrder) {
  const auto parts = read("robot_z_m,point,robot_x_m,robot_y_m\n0.25,P,0.45,-0.1\n");
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_DOUBLE_EQ(parts[0].robot_m.z(), 0.25);
  EXPECT_DOUBLE_EQ(parts[0].robot_m.x(), 0.45);
}

TEST_F(PartsCsv, TakesTheTargetRowsOfAMeasurementCsv) {
  const auto parts = read(
      "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm,config,"
      "q1_rad,repeat\n"
      "F1,fiducial,1,2,3,4,5,6,0,0.1,0\n"
      "T1,target,10,20,30,4,5,6,0,0.1,0\n"
      "T1,target,10,20,30,4.1,5,6,0,0.1,1\n"
      "T1,TARGET,10,20,30,4,5,6,1,0.2,0\n"
      "T2,target,40,50,60,4,5,6,0,0.1,0\n");
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].point, "T1");
  EXPECT_EQ(parts[1].point, "T2");
}

TEST_F(PartsCsv, EmptyOrNoHeader) {
  EXPECT_TRUE(fails("", 0, "empty file"));
  EXPECT_TRUE(fails("# only a comment\n\n", 0, "no header line"));
  EXPECT_TRUE(fails("point,robot_x_mm,robot_y_mm,robot_z_mm\n# none\n", 1, "header only"));
}

TEST_F(PartsCsv, BadHeader) {
  EXPECT_TRUE(fails("point,robot_x_mm,robot_y_mm\nP,1,2\n", 1, "missing column 'robot_z_mm'"));
  EXPECT_TRUE(fails("robot_x_mm,robot_y_mm,robot_z_mm\n1,2,3\n", 1, "missing column 'point'"));
  EXPECT_TRUE(fails("point,robot_x_mm,robot_y_mm,robot_z_mm,colour\nP,1,2,3,red\n", 1,
                    "unknown column 'colour'"));
  EXPECT_TRUE(fails("point,robot_x_mm,robot_y_m,robot_z_mm\nP,1,2,3\n", 1, "mixed length units"));
  EXPECT_TRUE(fails("point,robot_x,robot_y_mm,robot_z_mm\nP,1,2,3\n", 1, "no unit suffix"));
  EXPECT_TRUE(fails("point,robot_x_in,robot_y_mm,robot_z_mm\nP,1,2,3\n", 1, "_mm or _m"));
  EXPECT_TRUE(
      fails("point,point,robot_x_mm,robot_y_mm,robot_z_mm\nP,P,1,2,3\n", 1, "duplicate column"));
  EXPECT_TRUE(fails("point,,robot_x_mm,robot_y_mm,robot_z_mm\nP,,1,2,3\n", 1, "empty column name"));
  EXPECT_TRUE(fails("point,part,robot_x_mm,robot_y_mm,robot_z_mm\nP,Q,1,2,3\n", 1,
                    "unknown column 'part'"));
}

TEST_F(PartsCsv, BadRows) {
  const std::string h = "point,robot_x_mm,robot_y_mm,robot_z_mm\n";
  EXPECT_TRUE(fails(h + "P,1,2\n", 2, "expected 4 fields"));
  EXPECT_TRUE(fails(h + "P,1,2,3,4\n", 2, "expected 4 fields"));
  EXPECT_TRUE(fails(h + "P,1,two,3\n", 2, "not a finite number: 'two'"));
  EXPECT_TRUE(fails(h + "P,1,nan,3\n", 2, "not a finite number"));
  EXPECT_TRUE(fails(h + "P,1,inf,3\n", 2, "not a finite number"));
  EXPECT_TRUE(fails(h + ",1,2,3\n", 2, "empty point label"));
  EXPECT_TRUE(fails(h + "\"P\",1,2,3\n", 2, "quoted"));
  EXPECT_TRUE(fails(h + "P,1,2,3\nQ,1,2,3\nP,1,2,4\n", 4,
                    "part point 'P' has another position than on line 2"));
  EXPECT_TRUE(fails(h + "P,1,2,\x01\n", 2, "control"));
}

TEST_F(PartsCsv, MeasurementFileProblems) {
  const std::string h = "point,role,robot_x_mm,robot_y_mm,robot_z_mm\n";
  EXPECT_TRUE(fails(h + "F,fiducial,1,2,3\n", 1, "every row is a fiducial"));
  EXPECT_TRUE(fails(h + "T,tgt,1,2,3\n", 2, "role must be 'fiducial' or 'target'"));
  EXPECT_TRUE(fails("point,role,sensor_x_mm,sensor_y_mm,sensor_z_mm\nT,target,1,2,3\n", 1,
                    "missing column 'robot_x_mm'"));
}

TEST_F(PartsCsv, MissingFileOrDirectory) {
  const std::string missing = dir_.file("nope.csv");
  EXPECT_TRUE(throws_file_error([&] { (void)read_parts_csv(missing); }, missing, 0, "cannot open"));
  const std::string dir = dir_.path().string();
  EXPECT_TRUE(throws_file_error([&] { (void)read_parts_csv(dir); }, dir, 0, "is a directory"));
}

}  // namespace
}  // namespace vrreg::io
