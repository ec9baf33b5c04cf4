// SPDX-License-Identifier: Apache-2.0
// Approach directions of a measurement CSV (lost motion): from the rows' visiting order by
// default, or from the from_q columns; none without joints.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "io_test_helpers.hpp"
#include "vrreg/io/measurement_csv.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::throws_file_error;

const std::string kApproachHeader =
    "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm";

MeasurementSet parse_approach(const std::string& text) {
  std::istringstream in(text);
  return parse_measurement_csv(in, "test.csv", {});
}

using Signs = std::vector<double>;

TEST(ReadCsvApproach, FromTheRowOrder) {
  // A, A (a repeat), B, C, D: q1 goes up, up, down, stays; q2 stays, then goes down, then up.
  const MeasurementSet set = parse_approach(kApproachHeader +
                                            ",q1_rad,q2_rad,repeat\n"
                                            "A,fiducial,0,0,0,0,0,0,0.1,0.5,0\n"
                                            "A,fiducial,0,0,0,0,0,0,0.1,0.5,1\n"
                                            "B,fiducial,1,0,0,1,0,0,0.2,0.5,0\n"
                                            "C,fiducial,2,0,0,2,0,0,0.15,0.4,0\n"
                                            "D,target,3,0,0,3,0,0,0.15,0.45,0\n");
  EXPECT_EQ(set.approach, ApproachSource::kRowOrder);
  ASSERT_EQ(set.locations.size(), 4u);
  EXPECT_EQ(set.locations[0].approach_sign, (Signs{0, 0}));  // the first row: unknown
  EXPECT_EQ(set.locations[1].approach_sign, (Signs{1, 0}));  // q2 has not moved yet
  EXPECT_EQ(set.locations[2].approach_sign, (Signs{-1, -1}));
  EXPECT_EQ(set.locations[3].approach_sign, (Signs{-1, 1}));  // q1 stayed: keeps its side
}

TEST(ReadCsvApproach, FromTheFromColumnsInDegrees) {
  const MeasurementSet set = parse_approach(kApproachHeader +
                                            ",q1_deg,q2_deg,from_q2_deg,from_q1_deg\n"
                                            "A,fiducial,0,0,0,0,0,0,10,20,25,5\n"
                                            "B,fiducial,1,0,0,1,0,0,10,20,20,11\n");
  EXPECT_EQ(set.approach, ApproachSource::kFromJoints);
  EXPECT_EQ(set.locations[0].approach_sign, (Signs{1, -1}));
  EXPECT_EQ(set.locations[1].approach_sign, (Signs{-1, 0}));  // q2 did not move: unknown
}

TEST(ReadCsvApproach, NoneWithoutJoints) {
  const MeasurementSet set = parse_approach(kApproachHeader + "\nA,fiducial,0,0,0,0,0,0\n");
  EXPECT_EQ(set.approach, ApproachSource::kNone);
  EXPECT_TRUE(set.locations[0].approach_sign.empty());
}

TEST(ReadCsvApproach, RepeatsFromDifferentSidesLeaveTheJointUnknown) {
  // The same location read again after a move away (no visit column): q1 arrived from below, then
  // from above.
  const MeasurementSet set = parse_approach(kApproachHeader +
                                            ",q1_rad\n"
                                            "A,fiducial,0,0,0,0,0,0,0.0\n"
                                            "B,fiducial,1,0,0,1,0,0,0.1\n"
                                            "C,fiducial,2,0,0,2,0,0,0.2\n"
                                            "B,fiducial,1,0,0,1,0,0,0.1\n");
  ASSERT_EQ(set.locations.size(), 3u);
  EXPECT_EQ(set.locations[1].approach_sign, (Signs{0}));
  EXPECT_EQ(set.locations[2].approach_sign, (Signs{1}));
}

TEST(ReadCsvApproach, BadFromColumnsNameFileAndLine) {
  const auto header_error = [](const std::string& columns, const std::string& message) {
    return throws_file_error([&] { (void)parse_approach(kApproachHeader + columns + "\n"); },
                             "test.csv", 1, message);
  };
  EXPECT_TRUE(header_error(",q1_rad,q2_rad,from_q1_rad", "one per joint column"));
  EXPECT_TRUE(header_error(",from_q1_rad", "one per joint column: 1 from_q, 0 q"));
  EXPECT_TRUE(header_error(",q1_rad,from_q1_deg", "mixed angle units"));
  EXPECT_TRUE(header_error(",q1_rad,from_q1", "needs the unit suffix _rad or _deg"));
  EXPECT_TRUE(header_error(",q1_rad,from_x_rad", "unknown column 'from_x_rad'"));
  EXPECT_TRUE(header_error(",q1_rad,from_q1_rad,from_q1_rad", "duplicate column"));
  EXPECT_TRUE(throws_file_error(
      [&] {
        (void)parse_approach(kApproachHeader +
                             ",q1_rad,from_q1_rad\nA,fiducial,0,0,0,0,0,0,0.1,nan\n");
      },
      "test.csv", 2, "from_q1_rad"));
}

}  // namespace
}  // namespace vrreg::io
