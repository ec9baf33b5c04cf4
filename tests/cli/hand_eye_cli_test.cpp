// SPDX-License-Identifier: Apache-2.0
// Hand-eye registration from the command line (docs/hand-eye.md): plan with offset
// poses and a URScript program, simulate a cell whose marker offset is unknown, register with the
// offset estimated, evaluate, export; and the paper's one-orientation layout refused.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kParts =
    "point,robot_x_mm,robot_y_mm,robot_z_mm\n"
    "P0,380,-90,210\nP1,380,0,210\nP2,380,90,210\nP3,520,-90,290\nP4,520,0,290\nP5,520,90,290\n";

class HandEyeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    write_text(dir_ / "parts.csv", kParts);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string p(const char* name) const { return "'" + (dir_ / name).string() + "'"; }
  fs::path dir_;
};

TEST_F(HandEyeCli, PlanSimulateRegisterEvaluateExport) {
  const CliResult plan =
      run_vrreg("plan --parts " + p("parts.csv") +
                " --robot ur5 --halfwidth-mm 20 --spacing-mm 20 "
                "--offset-tilt-deg 20 -o " +
                p("plan.csv") + " --export urscript --program " + p("plan.script"));
  ASSERT_EQ(plan.status, 0) << plan.err;
  const std::string script = read_text(dir_ / "plan.script");
  EXPECT_NE(script.find("def vrreg_plan():"), std::string::npos);
  EXPECT_NE(script.find("offset-0-0"), std::string::npos);
  const CliResult sim = run_vrreg("simulate ur5 --plan " + p("plan.csv") +
                                  " --unknown-marker --seed 1 -o " + p("cell.csv"));
  ASSERT_EQ(sim.status, 0) << sim.err;
  EXPECT_NE(sim.out.find("true marker in the flange frame [35.000, -25.000, 85.000] mm"),
            std::string::npos)
      << sim.out;
  const CliResult reg = run_vrreg("register --fiducials " + p("cell.csv") +
                                  " --estimate-marker-offset --robot ur5 --cube-mm 20 -o " +
                                  p("model.json") + " --json");
  ASSERT_EQ(reg.status, 0) << reg.err;
  const json r = json::parse(reg.out);
  const double truth[3] = {35.0, -25.0, 85.0};
  for (int a = 0; a < 3; ++a) {  // the test bed's wrist errors bias it by ~1-2 mm (hand-eye.md)
    EXPECT_NEAR(r["p_flange_marker_mm"][a].get<double>(), truth[a], 3.0) << a;
    EXPECT_GT(r["p_std_mm"][a].get<double>(), 0.0);
  }
  EXPECT_EQ(r["n_fiducials"].get<int>(), 6 * 64);
  const CliResult eval =
      run_vrreg("evaluate --model " + p("model.json") + " --targets " + p("cell.csv") + " --json");
  ASSERT_EQ(eval.status, 0) << eval.err;
  const json e = json::parse(eval.out);
  EXPECT_EQ(e["n_targets"].get<int>(), 6);
  EXPECT_LT(e["cor_rms_t_mm"].get<double>(), 0.5);
  // The model kept the arm to its marker: auto (the joint model among its candidates) needs no
  // --robot.
  const CliResult automatic = run_vrreg("evaluate --model " + p("model.json") + " --targets " +
                                        p("cell.csv") + " --interpolation auto --json");
  ASSERT_EQ(automatic.status, 0) << automatic.err;
  const json a = json::parse(automatic.out);
  ASSERT_TRUE(a.contains("cross_validation")) << automatic.out;
  EXPECT_NE(a["cross_validation"].dump().find("joint"), std::string::npos) << automatic.out;

  const CliResult yaml = run_vrreg("export --model " + p("model.json") + " --format yaml");
  ASSERT_EQ(yaml.status, 0) << yaml.err;
  const YAML::Node doc = YAML::Load(yaml.out);
  EXPECT_NEAR(doc["transformation"]["x"].as<double>() * 1e3, r["translation_mm"][0].get<double>(),
              1e-9);
  EXPECT_NEAR(doc["marker_offset"]["z"].as<double>() * 1e3,
              r["p_flange_marker_mm"][2].get<double>(), 1e-9);
  const CliResult urdf =
      run_vrreg("export --model " + p("model.json") + " --format urdf -o " + p("cell.urdf"));
  ASSERT_EQ(urdf.status, 0) << urdf.err;
  EXPECT_NE(read_text(dir_ / "cell.urdf").find("robot_base_to_sensor"), std::string::npos);
}

// Every register path that uses a robot keeps it (to the marker) in the model, so that evaluate's
// joint model (and auto, which weighs it) never asks for --robot again.
TEST_F(HandEyeCli, EveryRegisterPathWithARobotKeepsIt) {
  ASSERT_EQ(run_vrreg("plan --parts " + p("parts.csv") +
                      " --robot ur5 --halfwidth-mm 20 --spacing-mm 20 --offset-tilt-deg 20 -o " +
                      p("plan.csv"))
                .status,
            0);
  ASSERT_EQ(run_vrreg("simulate ur5 --plan " + p("plan.csv") + " --unknown-marker --seed 1 -o " +
                      p("cell.csv"))
                .status,
            0);
  for (const std::string how : {"--robot ur5", "--marker-offset-mm 35 -25 85 --robot ur5",
                                "--estimate-marker-offset --robot ur5"}) {
    const CliResult reg =
        run_vrreg("register --fiducials " + p("cell.csv") + " " + how + " -o " + p("m.json"));
    ASSERT_EQ(reg.status, 0) << how << ": " << reg.err;
    EXPECT_TRUE(json::parse(read_text(dir_ / "m.json")).contains("robot")) << how;
    const CliResult eval = run_vrreg("evaluate --model " + p("m.json") + " --targets " +
                                     p("cell.csv") + " --interpolation joint --json");
    ASSERT_EQ(eval.status, 0) << how << ": " << eval.err;
    EXPECT_EQ(json::parse(eval.out)["interpolation"], "joint") << how;
  }
}

TEST_F(HandEyeCli, OneOrientationIsRefusedAsUnobservable) {
  ASSERT_EQ(run_vrreg("simulate ur5 A2 --unknown-marker --seed 2 -o " + p("a2.csv")).status, 0);
  const CliResult reg = run_vrreg("register --fiducials " + p("a2.csv") +
                                  " --estimate-marker-offset --robot ur5 -o " + p("m.json"));
  EXPECT_EQ(reg.status, 1);
  EXPECT_NE(reg.err.find("not observable"), std::string::npos) << reg.err;
  EXPECT_FALSE(fs::exists(dir_ / "m.json"));
}

TEST_F(HandEyeCli, BadUsage) {
  ASSERT_EQ(run_vrreg("simulate ur5 A2 --seed 2 -o " + p("a2.csv")).status, 0);
  EXPECT_NE(run_vrreg("register --fiducials " + p("a2.csv") + " --estimate-marker-offset").status,
            0);  // no --robot
  // --robot alone is not the hand-eye registration: it is stored for the joint-space field model.
  ASSERT_EQ(run_vrreg("register --fiducials " + p("a2.csv") + " --robot ur5 -o " + p("r.json"))
                .status,
            0);
  EXPECT_NE(read_text(dir_ / "r.json").find("\"robot\""), std::string::npos);
  EXPECT_NE(
      run_vrreg("register --fiducials " + p("a2.csv") + " --estimate-marker-offset --robot lwr4")
          .status,
      0);  // 6 joints in the file, 7 in the robot
  EXPECT_NE(run_vrreg("export --model " + p("a2.csv") + " --format yaml").status, 0);
  EXPECT_NE(run_vrreg("simulate ur5 A2 --marker-flange-mm 1 2 -o " + p("x.csv")).status, 0);
}

}  // namespace
}  // namespace vrreg::testing
