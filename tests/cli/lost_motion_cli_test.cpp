// SPDX-License-Identifier: Apache-2.0
// register --lost-motion as a user runs it: a UR5 simulated with lost motion (error-model file),
// its rows in visiting order with joints; register prints each joint's play in arc-minutes with
// its sd (text and --json), the model file keeps the term and evaluate restores it; what cannot
// fit the term is refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

class LostMotionCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return "'" + (dir_ / name).string() + "'"; }
  // A1 of the UR5 test bed with lost motion 0.8, 0.2, 0.15, 0.7, 0.6, 0.4 arc-min.
  void simulate_backlash() {
    ASSERT_EQ(run_vrreg("simulate ur5 --write-errors " + path("e.json")).status, 0);
    std::string text = read_text(dir_ / "e.json");
    const std::string key = "\"repeatability_sigma_mm\"";
    ASSERT_NE(text.find(key), std::string::npos) << text;
    text.insert(text.find(key), "\"lost_motion_arcmin\": [0.8, 0.2, 0.15, 0.7, 0.6, 0.4], ");
    write_text(dir_ / "e.json", text);
    const CliResult r =
        run_vrreg("simulate ur5 A1 --seed 2 --errors " + path("e.json") + " -o " + path("a1.csv"));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  fs::path dir_;
};

TEST_F(LostMotionCli, RegisterPrintsThePlaysAndEvaluateRestoresTheTerm) {
  simulate_backlash();
  const std::string reg = "register --fiducials " + path("a1.csv") +
                          " --sigma-rep-mm 0.1 --robot ur5 --interpolation trilinear";
  const CliResult text = run_vrreg(reg + " --lost-motion on -o " + path("m.json"));
  ASSERT_EQ(text.status, 0) << text.err;
  std::printf("%s", text.out.c_str());
  EXPECT_NE(text.out.find("lost motion                   applied"), std::string::npos) << text.out;
  const std::size_t at = text.out.find("    joint 1 ");
  ASSERT_NE(at, std::string::npos) << text.out;
  double play_arcmin = 0.0;
  double sd_arcmin = 0.0;
  ASSERT_EQ(std::sscanf(text.out.c_str() + at, "    joint 1 %lf arcmin (sd %lf)", &play_arcmin,
                        &sd_arcmin),
            2)
      << text.out.substr(at, 80);
  // Joint 1 moves the marker most: its play (simulated 0.8 arc-min) comes back within 3 sd.
  EXPECT_NEAR(play_arcmin, 0.8, 3.0 * sd_arcmin);
  EXPECT_GT(sd_arcmin, 0.0);

  const CliResult as_json = run_vrreg(reg + " --lost-motion on --json");
  ASSERT_EQ(as_json.status, 0) << as_json.err;
  EXPECT_NE(as_json.out.find("\"lost_motion\""), std::string::npos) << as_json.out;
  EXPECT_NE(as_json.out.find("\"play_arcmin\""), std::string::npos) << as_json.out;

  // The model file keeps the term and the fiducials' directions: evaluate restores it.
  const std::string model = read_text(dir_ / "m.json");
  EXPECT_NE(model.find("\"lost_motion\""), std::string::npos);
  EXPECT_NE(model.find("\"approach_sign\""), std::string::npos);
  const CliResult ev =
      run_vrreg("evaluate --model " + path("m.json") + " --targets " + path("a1.csv") + " --json");
  ASSERT_EQ(ev.status, 0) << ev.err;
  EXPECT_NE(ev.out.find("\"n_targets\": 120"), std::string::npos) << ev.out;

  // Off: no term, no lines about it.
  const CliResult off = run_vrreg(reg + " --lost-motion off");
  ASSERT_EQ(off.status, 0) << off.err;
  EXPECT_EQ(off.out.find("lost motion"), std::string::npos) << off.out;
}

TEST_F(LostMotionCli, RefusesWhatCannotFitTheTerm) {
  simulate_backlash();
  // No robot for the joints; the paper's linear stencils fit no corrector at register.
  for (const std::string flags :
       {" --interpolation trilinear --lost-motion on", " --robot ur5 --lost-motion on"}) {
    const CliResult r = run_vrreg("register --fiducials " + path("a1.csv") + flags);
    EXPECT_NE(r.status, 0) << flags;
    EXPECT_NE(r.err.find("lost motion"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const CliResult bad =
      run_vrreg("register --fiducials " + path("a1.csv") + " --lost-motion maybe");
  EXPECT_NE(bad.status, 0);
}

}  // namespace
}  // namespace vrreg::testing
