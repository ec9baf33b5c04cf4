// SPDX-License-Identifier: Apache-2.0
// Predicting a plan's accuracy before the robot runs it (Procedure 1, paper section 6):
// vrreg plan -> vrreg simulate TESTBED --plan -> vrreg register -> vrreg evaluate --cube-mm.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kThreeParts =
    "point,robot_x_mm,robot_y_mm,robot_z_mm\n"
    "hole_A,420,-140,250\nhole_B,480,-140,250\npin_C,480,-60,260\n";

class SimulatePlanCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    write_text(dir_ / "parts.csv", kThreeParts);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string p(const char* name) const { return "'" + (dir_ / name).string() + "'"; }
  fs::path dir_;
};

TEST_F(SimulatePlanCli, PlanSimulateRegisterEvaluate) {
  ASSERT_EQ(run_vrreg("plan --parts " + p("parts.csv") +
                      " --halfwidth-mm 10 --spacing-mm 5 --robot ur5 -o " + p("plan.csv"))
                .status,
            0);
  const CliResult sim =
      run_vrreg("simulate ur5 --plan " + p("plan.csv") + " --seed 3 -o " + p("measured.csv"));
  ASSERT_EQ(sim.status, 0) << sim.err;
  EXPECT_NE(sim.out.find("3 targets"), std::string::npos) << sim.out;
  const std::string measured = read_text(dir_ / "measured.csv");
  EXPECT_NE(measured.find("dataset plan, seed 3"), std::string::npos);
  const CliResult again =
      run_vrreg("simulate ur5 --plan " + p("plan.csv") + " --seed 3 -o " + p("again.csv"));
  ASSERT_EQ(again.status, 0);
  EXPECT_TRUE(read_text(dir_ / "again.csv") == measured) << "same seed, same bytes";

  const CliResult reg =
      run_vrreg("register --fiducials " + p("measured.csv") + " --json -o " + p("model.json"));
  ASSERT_EQ(reg.status, 0) << reg.err;
  EXPECT_EQ(json::parse(reg.out)["n_fiducials"], 3 * 216);
  const CliResult eval = run_vrreg("evaluate --model " + p("model.json") + " --targets " +
                                   p("measured.csv") + " --cube-mm 5 --json");
  ASSERT_EQ(eval.status, 0) << eval.err;
  const json e = json::parse(eval.out);
  EXPECT_EQ(e["n_targets"], 3);
  EXPECT_EQ(e["n_flagged"], 0);
  // The default UR5 misses by ~0.5-2 mm; 5 mm octuplets bring it near the noise floor.
  EXPECT_GT(e["unc_rms_t_mm"].get<double>(), 0.2);
  EXPECT_LT(e["cor_rms_t_mm"].get<double>(), 0.25);
  EXPECT_GT(e["gamma_percent"].get<double>(), 50.0);
}

TEST_F(SimulatePlanCli, RefusesAPlanForAnotherRobotOrWithoutJoints) {
  ASSERT_EQ(run_vrreg("plan --parts " + p("parts.csv") +
                      " --halfwidth-mm 5 --spacing-mm 5 --robot ur5 --tool-mm 0 0 0 -o " +
                      p("flange.csv"))
                .status,
            0);
  const CliResult r = run_vrreg("simulate ur5 --plan " + p("flange.csv") + " -o " + p("m.csv"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("flange.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("another robot or tool"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "m.csv"));

  write_text(dir_ / "bare.csv",
             "point,role,robot_x_mm,robot_y_mm,robot_z_mm\nA,target,450,0,250\n");
  const CliResult bare = run_vrreg("simulate ur5 --plan " + p("bare.csv") + " -o " + p("m.csv"));
  EXPECT_EQ(bare.status, 1);
  EXPECT_NE(bare.err.find("no joint columns"), std::string::npos) << bare.err;
  EXPECT_NE(run_vrreg("simulate ur5 A1 --plan " + p("bare.csv") + " -o " + p("m.csv")).status, 0);
}

}  // namespace
}  // namespace vrreg::testing
