// SPDX-License-Identifier: Apache-2.0
// Every kind of bad measurement file gives one FileError line naming the file and the line.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "io_test_helpers.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/io/measurement_csv.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

const std::string kBadInputHeader =
    "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n";
const std::string kRow = "P1,fiducial,1,2,3,4,5,6\n";

class BadCsv : public ::testing::Test {
 protected:
  // Writes `content` and expects reading it to fail at `line` with `fragment` in the message.
  ::testing::AssertionResult fails(const std::string& content, std::size_t line,
                                   const std::string& fragment,
                                   const CsvReadOptions& options = {}) {
    const std::string path = dir_.write("bad.csv", content);
    return throws_file_error([&] { (void)read_measurement_csv(path, options); }, path, line,
                             fragment);
  }
  TempDir dir_;
};

TEST_F(BadCsv, EmptyFile) { EXPECT_TRUE(fails("", 0, "empty file")); }
TEST_F(BadCsv, OnlyCommentsAndBlankLines) {
  EXPECT_TRUE(fails("# a comment\n\n   \n", 0, "no header line"));
}
TEST_F(BadCsv, HeaderOnly) { EXPECT_TRUE(fails("# c\n" + kBadInputHeader, 2, "no data rows")); }
TEST_F(BadCsv, HeaderOnlyWithTrailingComments) {
  EXPECT_TRUE(fails(kBadInputHeader + "# nothing\n\n", 1, "no data rows"));
}
TEST_F(BadCsv, MissingColumn) {
  EXPECT_TRUE(fails("point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm\n" +
                        std::string("P1,fiducial,1,2,3,4,5\n"),
                    1, "missing column 'sensor_z_mm'"));
}
TEST_F(BadCsv, MissingRobotColumnWhenRequired) {
  EXPECT_TRUE(fails("point,role,sensor_x_m,sensor_y_m,sensor_z_m\nP1,target,1,2,3\n", 1,
                    "missing column 'robot_x_m'"));
}
TEST_F(BadCsv, PartialRobotColumnsWhenNotRequired) {
  CsvReadOptions options;
  options.require_robot = false;
  EXPECT_TRUE(fails("point,role,robot_x_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\nP,target,1,2,3,4\n",
                    1, "missing column 'robot_y_mm'", options));
}
TEST_F(BadCsv, MissingPointColumn) {
  EXPECT_TRUE(
      fails("role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n"
            "fiducial,1,2,3,4,5,6\n",
            1, "missing column 'point'"));
}
TEST_F(BadCsv, DuplicateColumn) {
  EXPECT_TRUE(
      fails("point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,"
            "sensor_z_mm,role\n",
            1, "duplicate column 'role' (columns 2 and 9)"));
}
TEST_F(BadCsv, SameCoordinateInTwoUnits) {
  EXPECT_TRUE(
      fails("point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,"
            "sensor_z_mm,robot_x_m\n",
            1, "duplicate column 'robot_x_m'"));
}
TEST_F(BadCsv, UnknownColumnListsAllowedOnes) {
  EXPECT_TRUE(
      fails("point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,"
            "sensor_z_mm,temperature\n",
            1, "unknown column 'temperature' (allowed: point, role, robot_x_mm"));
}
TEST_F(BadCsv, UnknownUnitSuffix) {
  EXPECT_TRUE(
      fails("point,role,robot_x_cm,robot_y_cm,robot_z_cm,sensor_x_cm,sensor_y_cm,"
            "sensor_z_cm\n" +
                kRow,
            1, "column 'robot_x_cm': unknown unit suffix '_cm'"));
}
TEST_F(BadCsv, MissingUnitSuffix) {
  EXPECT_TRUE(fails("point,role,robot_x,robot_y,robot_z,sensor_x,sensor_y,sensor_z\n" + kRow, 1,
                    "column 'robot_x' has no unit suffix"));
}
TEST_F(BadCsv, MixedLengthUnits) {
  EXPECT_TRUE(
      fails("point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_m,sensor_y_m,"
            "sensor_z_m\n" +
                kRow,
            1, "mixed length units: column 'sensor_x_m' uses _m but column 'robot_x_mm'"));
}
TEST_F(BadCsv, MixedJointUnits) {
  EXPECT_TRUE(fails(kBadInputHeader.substr(0, kBadInputHeader.size() - 1) + ",q1_rad,q2_deg\n", 1,
                    "mixed angle units: column 'q2_deg'"));
}
TEST_F(BadCsv, UnknownJointUnit) {
  EXPECT_TRUE(fails(kBadInputHeader.substr(0, kBadInputHeader.size() - 1) + ",q1_grad\n", 1,
                    "column 'q1_grad': unknown unit suffix '_grad'"));
}
TEST_F(BadCsv, JointColumnsWithGap) {
  EXPECT_TRUE(fails(kBadInputHeader.substr(0, kBadInputHeader.size() - 1) + ",q1_rad,q3_rad\n", 1,
                    "missing column 'q2_rad'"));
}
TEST_F(BadCsv, JointColumnZero) {
  EXPECT_TRUE(fails(kBadInputHeader.substr(0, kBadInputHeader.size() - 1) + ",q0_rad\n", 1,
                    "column 'q0_rad'"));
}
TEST_F(BadCsv, EmptyColumnName) {
  EXPECT_TRUE(
      fails(kBadInputHeader.substr(0, kBadInputHeader.size() - 1) + ",\n", 1, "empty column name"));
}
TEST_F(BadCsv, NanValue) {
  EXPECT_TRUE(fails(kBadInputHeader + kRow + "P2,fiducial,1,2,nan,4,5,6\n", 3,
                    "column 'robot_z_mm': 'nan' is not a finite number"));
}
TEST_F(BadCsv, InfValue) {
  EXPECT_TRUE(
      fails(kBadInputHeader + "P2,fiducial,1,2,3,-inf,5,6\n", 2, "'-inf' is not a finite number"));
}
TEST_F(BadCsv, OverflowingValue) {
  EXPECT_TRUE(
      fails(kBadInputHeader + "P2,fiducial,1,2,3,1e400,5,6\n", 2, "'1e400' is not a finite"));
}
TEST_F(BadCsv, OutOfRangeValue) {
  // Finite, but squared in a registration's sums it overflows: refused as read, naming the point.
  EXPECT_TRUE(fails(kBadInputHeader + "P2,fiducial,1e308,2,3,4,5,6\n", 2,
                    "point 'P2', column 'robot_x_mm': 1e308 is out of range"));
  EXPECT_TRUE(fails(kBadInputHeader + "P2,fiducial,1,2,3,4,5,-2e9\n", 2,
                    "column 'sensor_z_mm': -2e9 is out of range"));
}
TEST_F(BadCsv, NonNumericValue) {
  EXPECT_TRUE(fails(kBadInputHeader + "P2,fiducial,1,2,3,4,abc,6\n", 2,
                    "column 'sensor_y_mm': 'abc' is not a finite number"));
}
TEST_F(BadCsv, TrailingGarbageAfterNumber) {
  EXPECT_TRUE(
      fails(kBadInputHeader + "P2,fiducial,1,2,3,4,5,6.0mm\n", 2, "'6.0mm' is not a finite"));
}
TEST_F(BadCsv, EmptyValue) {
  EXPECT_TRUE(
      fails(kBadInputHeader + "P2,fiducial,1,,3,4,5,6\n", 2, "column 'robot_y_mm': empty value"));
}
TEST_F(BadCsv, ShortRow) {
  EXPECT_TRUE(fails(kBadInputHeader + kRow + "P2,fiducial,1,2,3,4,5\n", 3,
                    "short row: 7 fields, the header has 8"));
}
TEST_F(BadCsv, LongRow) {
  EXPECT_TRUE(fails(kBadInputHeader + "P2,fiducial,1,2,3,4,5,6,7\n", 2, "long row: 9 fields"));
}
TEST_F(BadCsv, EmptyPointLabel) {
  EXPECT_TRUE(fails(kBadInputHeader + " ,fiducial,1,2,3,4,5,6\n", 2, "empty point label"));
}
TEST_F(BadCsv, UnknownRole) {
  EXPECT_TRUE(fails(kBadInputHeader + "P1,fiducal,1,2,3,4,5,6\n", 2,
                    "unknown role 'fiducal' (expected fiducial, target or monitor)"));
}
TEST_F(BadCsv, AbbreviatedRoleIsNotAccepted) {
  EXPECT_TRUE(fails(kBadInputHeader + "P1,f,1,2,3,4,5,6\n", 2, "unknown role 'f'"));
}
TEST_F(BadCsv, NonIntegerConfig) {
  EXPECT_TRUE(
      fails("point,role,config,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,"
            "sensor_z_mm\nP1,fiducial,1.5,1,2,3,4,5,6\n",
            2, "column 'config': '1.5' is not an integer"));
}
TEST_F(BadCsv, NegativeRepeat) {
  EXPECT_TRUE(fails(kBadInputHeader.substr(0, kBadInputHeader.size() - 1) +
                        ",repeat\nP1,fiducial,1,2,3,4,5,6,-1\n",
                    2, "negative repeat"));
}
TEST_F(BadCsv, QuotedFieldIsRejected) {
  EXPECT_TRUE(fails(kBadInputHeader + "\"P1\",fiducial,1,2,3,4,5,6\n", 2,
                    "quoted fields are not supported"));
}
TEST_F(BadCsv, SamePointWithConflictingRole) {
  EXPECT_TRUE(fails(kBadInputHeader + kRow + "P2,target,0,0,0,0,0,0\nP1,target,1,2,3,4,5,6\n", 4,
                    "point 'P1' has role target here but fiducial on line 2"));
}
TEST_F(BadCsv, SamePointWithConflictingRobotCoordinates) {
  EXPECT_TRUE(
      fails(kBadInputHeader + kRow + "P1,fiducial,1,2,3.001,4,5,6\n", 3,
            "point 'P1' has robot position (1, 2, 3.001) mm here but (1, 2, 3) mm on line 2"));
}
TEST_F(BadCsv, ConflictAcrossConfigsOfOnePoint) {
  EXPECT_TRUE(
      fails("point,role,config,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,"
            "sensor_z_mm\nP1,fiducial,1,1,2,3,4,5,6\nP1,fiducial,2,1,2.5,3,4,5,6\n",
            3, "on line 2"));
}
TEST_F(BadCsv, SameLocationWithConflictingJoints) {
  const std::string header =
      kBadInputHeader.substr(0, kBadInputHeader.size() - 1) + ",config,q1_rad,q2_rad\n";
  EXPECT_TRUE(
      fails(header + "P1,fiducial,1,2,3,4,5,6,0,0.1,0.2\nP1,fiducial,1,2,3,4,5,6,0,0.1,0.3\n", 3,
            "point 'P1' config 0 has q2 = 0.3 rad here but 0.2 rad on line 2"));
}
TEST_F(BadCsv, NulBytes) {
  std::string row = kRow;
  row[4] = '\0';
  EXPECT_TRUE(fails(kBadInputHeader + row, 2, "NUL byte at column 5"));
}
TEST_F(BadCsv, InvalidUtf8) {
  EXPECT_TRUE(fails(kBadInputHeader + "P\xff,fiducial,1,2,3,4,5,6\n", 2, "invalid UTF-8"));
}
TEST_F(BadCsv, RandomBinaryGarbage) {
  Random rng(2024);
  for (int trial = 0; trial < 20; ++trial) {
    std::string garbage(4096, '\0');
    for (char& c : garbage) c = static_cast<char>(rng.below(256));
    const std::string path = dir_.write("garbage.csv", garbage);
    EXPECT_THROW((void)read_measurement_csv(path), FileError) << "trial " << trial;
  }
}
TEST_F(BadCsv, TwoMegabyteLineFailsFastWithBoundedMemory) {
  const std::string line(2 * 1024 * 1024, '7');
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(fails(kBadInputHeader + kRow + line + "\n", 3, "line longer than 1048576 bytes"));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}
TEST_F(BadCsv, HeaderLongerThanConfiguredLimit) {
  CsvReadOptions options;
  options.max_line_bytes = 40;
  EXPECT_TRUE(fails(kBadInputHeader + kRow, 1, "line longer than 40 bytes", options));
}
TEST_F(BadCsv, FileThatCannotBeOpened) {
  const std::string path = dir_.file("does_not_exist.csv");
  EXPECT_TRUE(throws_file_error([&] { (void)read_measurement_csv(path); }, path, 0,
                                "cannot open: No such file or directory"));
}
TEST_F(BadCsv, DirectoryInsteadOfFile) {
  const std::string path = dir_.path().string();
  EXPECT_TRUE(
      throws_file_error([&] { (void)read_measurement_csv(path); }, path, 0, "is a directory"));
}

CsvReadOptions sensor_only() {
  CsvReadOptions options;
  options.require_robot = false;
  return options;
}

TEST_F(BadCsv, MarkerOrientationNeedsAllFourColumns) {
  EXPECT_TRUE(fails("point,role,sensor_x_mm,sensor_y_mm,sensor_z_mm,sensor_qx,sensor_qy,sensor_qw\n"
                    "A,target,1,2,3,0,0,1\n",
                    1, "missing column 'sensor_qz'", sensor_only()));
}

TEST_F(BadCsv, MarkerOrientationNotUnit) {
  const std::string header =
      "point,role,sensor_x_mm,sensor_y_mm,sensor_z_mm,sensor_qx,sensor_qy,sensor_qz,sensor_qw\n";
  EXPECT_TRUE(fails(header + "A,target,1,2,3,0,0,0,1\nB,target,1,2,3,0,0,0,1.01\n", 3,
                    "not 1", sensor_only()));
  EXPECT_TRUE(fails(header + "A,target,1,2,3,0,0,0,0\n", 2, "not 1", sensor_only()));
  EXPECT_TRUE(fails(header + "A,target,1,2,3,0,0,x,1\n", 2, "sensor_qz", sensor_only()));
}

}  // namespace
}  // namespace vrreg::io
