// SPDX-License-Identifier: Apache-2.0
// A cell of fewer fiducials than any correction method needs (3: scattered needs 4) registers,
// and evaluate and correct still report: every target uncorrected, flagged "too few fiducials",
// the uncorrected TRE in both columns, and which method would need how many fiducials.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Three fiducials (a triangle: registrable) and four targets, robot and sensor in mm (the sensor
// 1 m away along x, turned 90 degrees about z, with small errors).
const std::string kCell =
    "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n"
    "F1,fiducial,400,0,200,0.1,-400,200\n"
    "F2,fiducial,500,0,200,-0.2,-500.1,200.2\n"
    "F3,fiducial,400,100,250,100.1,-400,250\n"
    "T1,target,420,10,210,10.3,-420,210.1\n"
    "T2,target,450,50,220,50,-450.2,220\n"
    "T3,target,480,20,230,20.2,-480,229.8\n"
    "T4,target,430,80,240,80,-430.1,240.3\n";

class SmallCellCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    write_text(dir_ / "cell.csv", kCell);
    const CliResult reg = run_vrreg("register --fiducials " + p("cell.csv") + " -o " + p("m.json"));
    ASSERT_EQ(reg.status, 0) << reg.err;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string p(const char* name) const { return "'" + (dir_ / name).string() + "'"; }
  fs::path dir_;
};

TEST_F(SmallCellCli, EvaluateReportsTheUncorrectedTreAndWhy) {
  for (const char* method : {"linear", "scattered", "kriging", "auto"}) {
    const CliResult eval = run_vrreg("evaluate --model " + p("m.json") + " --targets " +
                                     p("cell.csv") + " --interpolation " + method + " --json");
    ASSERT_EQ(eval.status, 0) << method << ": " << eval.err;
    const json e = json::parse(eval.out);
    EXPECT_EQ(e["n_targets"].get<int>(), 4) << method;
    EXPECT_EQ(e["n_flagged"].get<int>(), 4) << method;
    EXPECT_EQ(e["n_corrected"].get<int>(), 0) << method;
    // The uncorrected error comes out on its own; no corrected figure is made up.
    EXPECT_GT(e["flagged_rms_t_mm"].get<double>(), 0.0) << method;
    EXPECT_TRUE(e["unc_rms_t_mm"].is_null()) << method;
    EXPECT_TRUE(e["cor_rms_t_mm"].is_null()) << method;
    EXPECT_TRUE(e["gamma_percent"].is_null()) << method;
    const std::string layout = e["layout"].get<std::string>();
    EXPECT_NE(layout.find("3 fiducials are fewer than any correction method needs"),
              std::string::npos)
        << layout;
    EXPECT_NE(layout.find("scattered and linear 4"), std::string::npos) << layout;
  }
  const CliResult text = run_vrreg("evaluate --model " + p("m.json") + " --targets " +
                                   p("cell.csv") + " --per-target " + p("pt.csv"));
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("not correctable               4 targets (too few fiducials"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("no target was corrected"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("gamma ="), std::string::npos) << text.out;
  const std::string per_target = read_text(dir_ / "pt.csv");
  EXPECT_NE(per_target.find("T1,,too few fiducials,"), std::string::npos) << per_target;
}

TEST_F(SmallCellCli, CorrectWritesTheUncorrectedMappingFlagged) {
  const CliResult c = run_vrreg("correct --model " + p("m.json") + " --points " + p("cell.csv") +
                                " -o " + p("out.csv"));
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("4 points (too few fiducials"), std::string::npos) << c.out;
  const std::string out = read_text(dir_ / "out.csv");
  EXPECT_NE(out.find("T4,,too few fiducials,"), std::string::npos) << out;
}

}  // namespace
}  // namespace vrreg::testing
