// SPDX-License-Identifier: Apache-2.0
// The plan file: written exactly and read back; bad plan files give one FileError line.
#include "vrreg/io/plan_csv.hpp"

#include <gtest/gtest.h>

#include "io_test_helpers.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

std::vector<PlanRow> sample_rows() {
  std::vector<PlanRow> rows(3);
  rows[0] = {"P.f0-0-0", Role::kFiducial,
             "P",        {0.4475, -0.1025, 0.2475},
             1,          {0.1, -1.2, 1.3, -0.3, -1.5707963267948966, 2.0},
             0};
  rows[1] = {
      "P", Role::kTarget, "P", {0.45, -0.1, 0.25}, 1, {0.11, -1.21, 1.31, -0.31, -1.57, 2.01}, 0};
  rows[2] = {"P.f1-0-0", Role::kFiducial,
             "P",        {0.4525, -0.1025, 0.2475},
             1,          {1.0 / 3.0, -1.2, 1.3, -0.3, -1.5, 2.0},
             0};
  return rows;
}

TEST(PlanCsv, RoundTripsExactly) {
  TempDir dir;
  const std::string path = dir.file("plan.csv");
  write_plan_csv(path, sample_rows(), {"vrreg plan", "robot: ur5\nspacing_mm: 5", ""});
  const std::string text = vrreg::testing::read_text(path);
  EXPECT_TRUE(
      text.starts_with("# vrreg plan\n# robot: ur5\n# spacing_mm: 5\n#\n"
                       "point,role,part,robot_x_mm,robot_y_mm,robot_z_mm,config,q1_rad,"))
      << text;
  const PlanFile back = read_plan_csv(path);
  ASSERT_EQ(back.rows.size(), 3u);
  EXPECT_EQ(back.n_joints, 6);
  EXPECT_TRUE(back.has_config);
  EXPECT_EQ(back.comments.front(), "vrreg plan");
  EXPECT_EQ(back.comments[1], "robot: ur5");
  const std::vector<PlanRow> rows = sample_rows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(back.rows[i].point, rows[i].point);
    EXPECT_EQ(back.rows[i].role, rows[i].role);
    EXPECT_EQ(back.rows[i].part, rows[i].part);
    EXPECT_EQ(back.rows[i].config, rows[i].config);
    EXPECT_EQ(back.rows[i].q_rad, rows[i].q_rad);  // exact
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(back.rows[i].robot_m(a), rows[i].robot_m(a), 1e-15);  // via mm
    }
  }
}

TEST(PlanCsv, WriterRefusesInconsistentRows) {
  std::vector<PlanRow> rows = sample_rows();
  rows[1].config.reset();
  EXPECT_THROW(format_plan_csv(rows), InputError);
  rows = sample_rows();
  rows[2].q_rad.pop_back();
  EXPECT_THROW(format_plan_csv(rows), InputError);
  rows = sample_rows();
  rows[0].point = "a,b";
  EXPECT_THROW(format_plan_csv(rows), InputError);
  rows = sample_rows();
  rows[0].robot_m.x() = NAN;
  EXPECT_THROW(format_plan_csv(rows), InputError);
  EXPECT_THROW(format_plan_csv({}), InputError);
}

TEST(PlanCsv, ReaderTakesMinimalPlansAndDegrees) {
  TempDir dir;
  const std::string path = dir.write("p.csv",
                                     "Robot_X_M,robot_y_m,robot_z_m,POINT,role,q1_deg,q2_deg\n"
                                     "0.4,0.1,0.2,A,fiducial,90,-90\n0.5,0.1,0.2,B,target,0,0\n");
  const PlanFile plan = read_plan_csv(path);
  ASSERT_EQ(plan.rows.size(), 2u);
  EXPECT_FALSE(plan.has_config);
  EXPECT_EQ(plan.n_joints, 2);
  EXPECT_DOUBLE_EQ(plan.rows[0].q_rad[0], 1.5707963267948966);
  EXPECT_TRUE(plan.rows[0].part.empty());
  EXPECT_EQ(plan.rows[1].role, Role::kTarget);
}

TEST(PlanCsv, BadPlanFiles) {
  TempDir dir;
  const auto fails = [&](const std::string& content, std::size_t line, const std::string& what) {
    const std::string path = dir.write("bad.csv", content);
    return throws_file_error([&] { (void)read_plan_csv(path); }, path, line, what);
  };
  const std::string h = "point,role,part,robot_x_mm,robot_y_mm,robot_z_mm,config,q1_rad\n";
  EXPECT_TRUE(fails("point,part,robot_x_mm,robot_y_mm,robot_z_mm\nA,P,1,2,3\n", 1,
                    "missing column 'role'"));
  EXPECT_TRUE(fails("point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm\nA,target,1,2,3,4\n",
                    1, "unknown column 'sensor_x_mm'"));
  EXPECT_TRUE(fails(h + "A,fiducial,P,1,2,3,0,0.5\nA,fiducial,P,1,2,3,0,0.5\n", 3,
                    "listed twice in the same configuration (first on line 2)"));
  EXPECT_TRUE(fails(h + "A,fiducial,P,1,2,3,x,0.5\n", 2, "config must be an integer"));
  EXPECT_TRUE(fails(h + "A,fiducial,P,1,2,3,0,nan\n", 2, "not a finite number"));
  EXPECT_TRUE(fails(h + "A,probe,P,1,2,3,0,0.5\n", 2, "role must be"));
  EXPECT_TRUE(fails(h, 1, "header only"));
  EXPECT_TRUE(fails("point,role,robot_x_mm,robot_y_mm,robot_z_mm,q2_rad\nA,target,1,2,3,4\n", 1,
                    "missing 'q1_rad'"));
  // Labels the writer could not write back (found by fuzzing: tests/fuzz/regressions/plan_csv).
  EXPECT_TRUE(
      fails(h + "A,fiducial,#P,1,2,3,0,0.5\n", 2, "part label '#P' has a quote or a leading '#'"));
  EXPECT_TRUE(fails("role,point,robot_x_mm,robot_y_mm,robot_z_mm\ntarget,#A,1,2,3\n", 2,
                    "point label '#A'"));
  EXPECT_TRUE(fails(h + "A\"x,fiducial,P,1,2,3,0,0.5\n", 2, "point label"));
}


TEST(PlanCsv, ViaRowsComeJustBeforeTheirLocationAndReadBackOntoIt) {
  TempDir dir;
  const std::string path = dir.file("plan.csv");
  std::vector<PlanRow> rows = sample_rows();
  rows[1].via = PlanVia{{0.451, -0.099, 0.252}, {0.08, -1.24, 1.28, -0.34, -1.6, 1.98}};
  write_plan_csv(path, rows);
  const std::string text = vrreg::testing::read_text(path);
  const auto via = text.find("\nP,via,P,");
  ASSERT_NE(via, std::string::npos) << text;
  EXPECT_LT(via, text.find("\nP,target,P,"));
  EXPECT_NE(text.find(",0.08,-1.24,", via), std::string::npos) << text;
  EXPECT_LT(text.find("\nP.f0-0-0,fiducial"), via);
  const PlanFile back = read_plan_csv(path);
  ASSERT_EQ(back.rows.size(), 3u);  // the via row is not a location
  EXPECT_FALSE(back.rows[0].via.has_value());
  ASSERT_TRUE(back.rows[1].via.has_value());
  EXPECT_EQ(back.rows[1].via->q_rad, rows[1].via->q_rad);
  EXPECT_NEAR((back.rows[1].via->robot_m - rows[1].via->robot_m).norm(), 0.0, 1e-15);
  EXPECT_EQ(back.rows[1].role, Role::kTarget);
  EXPECT_FALSE(back.rows[2].via.has_value());
  // A plan without via points is written as before: no via row.
  write_plan_csv(path, sample_rows());
  EXPECT_EQ(vrreg::testing::read_text(path).find(",via,"), std::string::npos);
}

TEST(PlanCsv, AViaRowMustLeadToItsLocation) {
  TempDir dir;
  const auto fails = [&](const std::string& content, std::size_t line, const std::string& what) {
    const std::string path = dir.write("bad.csv", content);
    return throws_file_error([&] { (void)read_plan_csv(path); }, path, line, what);
  };
  const std::string h = "point,role,part,robot_x_mm,robot_y_mm,robot_z_mm,config,q1_rad\n";
  EXPECT_TRUE(fails(h + "A,fiducial,P,1,2,3,0,0.5\nB,via,P,1,2,3,0,0.4\n", 3,
                    "via row of 'B' is the last row"));
  EXPECT_TRUE(fails(h + "B,via,P,1,2,3,0,0.4\nA,fiducial,P,1,2,3,0,0.5\n", 2,
                    "via row of 'B' is not followed by its location"));
  EXPECT_TRUE(fails(h + "A,via,P,1,2,3,0,0.4\nA,via,P,1,2,3,0,0.4\nA,fiducial,P,1,2,3,0,0.5\n",
                    2, "is not followed by its location"));
  EXPECT_TRUE(fails(h + "A,via,P,1,2,3,1,0.4\nA,fiducial,P,1,2,3,0,0.5\n", 2,
                    "is not followed by its location"));
}

}  // namespace
}  // namespace vrreg::io
