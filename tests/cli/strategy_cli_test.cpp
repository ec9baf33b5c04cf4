// SPDX-License-Identifier: Apache-2.0
// register / evaluate / correct with --strategy 1|2|3 (Procedure 2, paper section 4.4) on a small
// two-configuration cell, and every bad combination: one line on stderr naming the file.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "two_arm_cell.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class StrategyCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    cell_ = (dir_ / "cell.csv").string();
    write_text(cell_, two_arm_cell_csv());
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string q(const std::string& s) const { return "'" + s + "'"; }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  json run_json(const std::string& args) {
    const CliResult r = run_vrreg(args + " --json");
    EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
    return r.status == 0 ? json::parse(r.out) : json::object();
  }

  // Fails with exit status 1 and one line on stderr naming `file` and containing `words`.
  void expect_fails(const std::string& args, const std::string& file, const std::string& words) {
    const CliResult r = run_vrreg(args);
    EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }

  fs::path dir_;
  std::string cell_;
};

TEST_F(StrategyCli, Strategies2And3BeatStrategy1EndToEnd) {
  const std::string m1 = path("m1.json"), m2 = path("m2.json"), m3 = path("m3.json");
  const json r1 =
      run_json("register --fiducials " + q(cell_) + " --strategy 1 --config 1 -o " + q(m1));
  EXPECT_EQ(r1["strategy"], 1);
  EXPECT_EQ(r1["n_fiducials"], 117);
  for (const char* key : {"rotation", "translation_mm", "fre_mm", "sigma_l_mm", "n_fiducials"}) {
    EXPECT_TRUE(r1.contains(key)) << key;
  }
  const json e1 =
      run_json("evaluate --model " + q(m1) + " --targets " + q(cell_) + " --cube-mm 40");
  EXPECT_EQ(e1["strategy"], 1);
  EXPECT_EQ(e1["n_targets"], 8);

  const json r2 =
      run_json("register --fiducials " + q(cell_) + " --strategy 2 --config 1 -o " + q(m2));
  EXPECT_EQ(r2["strategy"], 2);
  EXPECT_DOUBLE_EQ(r2["switched_fraction"].get<double>(), 0.6);
  EXPECT_EQ(r2["switched_fraction"], r2["switched_points_fraction"]);
  EXPECT_EQ(r2["n_switched_points"], 75);
  EXPECT_EQ(r2["n_points"], 125);
  EXPECT_EQ(r2["n_switched_locations"], 150);
  EXPECT_EQ(r2["n_locations"], 250);
  EXPECT_DOUBLE_EQ(r2["switched_locations_fraction"].get<double>(), 0.6);
  EXPECT_LT(r2["sigma_l_mm"].get<double>(), r1["sigma_l_mm"].get<double>());
  const json e2 =
      run_json("evaluate --model " + q(m2) + " --targets " + q(cell_) + " --cube-mm 40");
  EXPECT_EQ(e2["strategy"], 2);
  EXPECT_DOUBLE_EQ(e2["switched_fraction"].get<double>(), 0.6);
  EXPECT_EQ(e2["n_targets"], 8);

  const json r3 = run_json("register --fiducials " + q(cell_) +
                           " --strategy 3 --seed 7 --cube-mm 40 -o " + q(m3));
  EXPECT_EQ(r3["strategy"], 3);
  EXPECT_EQ(r3["seed"], 7);
  EXPECT_EQ(r3["n_fiducials"], 8);
  EXPECT_EQ(r3["n_correction_fiducials"], 234);
  const json e3 = run_json("evaluate --model " + q(m3) + " --targets " + q(cell_) + " --config 1");
  EXPECT_EQ(e3["strategy"], 3);
  EXPECT_EQ(e3["seed"], 7);
  EXPECT_EQ(e3["n_targets"], 8);
  EXPECT_EQ(run_json("evaluate --model " + q(m3) + " --targets " + q(cell_))["n_targets"], 16);

  const double cor1 = e1["cor_rms_t_mm"].get<double>();
  EXPECT_LT(e2["cor_rms_t_mm"].get<double>(), 0.5 * cor1);
  EXPECT_LT(e3["cor_rms_t_mm"].get<double>(), 0.5 * cor1);
  EXPECT_GT(e3["gamma_percent"].get<double>(), e1["gamma_percent"].get<double>());

  // The text output prints the seed; the same seed gives the same registration.
  const CliResult text = run_vrreg("register --fiducials " + q(cell_) + " --strategy 3 --seed 7");
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("seed 7"), std::string::npos) << text.out;
  EXPECT_EQ(run_json("register --fiducials " + q(cell_) + " --strategy 3 --seed 7")["rotation"],
            r3["rotation"]);

  // correct follows the model's strategy.
  const CliResult c = run_vrreg("correct --model " + q(m3) + " --points " + q(cell_) +
                                " --config 2 -o " + q(path("out.csv")));
  EXPECT_EQ(c.status, 0) << c.err;
  EXPECT_NE(read_text(path("out.csv")).find("T111,2,ok"), std::string::npos);
}

TEST_F(StrategyCli, WithoutStrategyNothingChanges) {
  const json r = run_json("register --fiducials " + q(cell_) + " --config 1");
  EXPECT_TRUE(r["strategy"].is_null());
  EXPECT_FALSE(r.contains("switched_fraction"));
  EXPECT_FALSE(r.contains("seed"));
  EXPECT_EQ(r["n_fiducials"], 117);
}

TEST_F(StrategyCli, JointNormIsStoredAndMustMatchForStrategy2) {
  const std::string m = path("m.json");
  const json r = run_json("register --fiducials " + q(cell_) +
                          " --strategy 2 --config 2 --joint-norm linf -o " + q(m));
  EXPECT_EQ(r["joint_norm"], "linf");
  EXPECT_EQ(run_json("evaluate --model " + q(m) + " --targets " + q(cell_) +
                     " --cube-mm 40")["joint_norm"],
            "linf");
  expect_fails("evaluate --model " + q(m) + " --targets " + q(cell_) + " --joint-norm l2", m,
               "joint-norm linf");
}

TEST_F(StrategyCli, BadInputNamesTheFile) {
  TwoArmCellOptions no_config;
  no_config.with_config = false;
  const std::string plain = path("plain.csv");
  write_text(plain, two_arm_cell_csv(no_config));
  TwoArmCellOptions no_joints;
  no_joints.with_joints = false;
  const std::string jointless = path("jointless.csv");
  write_text(jointless, two_arm_cell_csv(no_joints));
  const std::string m1 = path("m1.json"), m3 = path("m3.json");

  expect_fails("register --fiducials " + q(plain) + " --strategy 2 --config 1", plain,
               "config column");
  expect_fails("register --fiducials " + q(jointless) + " --strategy 2 --config 1", jointless,
               "joint columns");
  expect_fails("register --fiducials " + q(jointless) + " --strategy 3", jointless,
               "joint columns");
  expect_fails("register --fiducials " + q(cell_) + " --strategy 2", cell_, "give --config");
  expect_fails("register --fiducials " + q(cell_) + " --strategy 3 --config 1", cell_, "--config");
  expect_fails("register --fiducials " + q(cell_) + " --strategy 1 --config 1 --seed 3", cell_,
               "--seed");
  EXPECT_EQ(run_vrreg("register --fiducials " + q(cell_) + " --strategy 4").status, 2);
  EXPECT_FALSE(fs::exists(m1));

  ASSERT_EQ(run_vrreg("register --fiducials " + q(cell_) + " --config 1 -o " + q(m1)).status, 0);
  expect_fails("evaluate --model " + q(m1) + " --targets " + q(cell_) + " --strategy 2", m1,
               "register again");
  ASSERT_EQ(run_vrreg("register --fiducials " + q(cell_) + " --strategy 3 -o " + q(m3)).status, 0);
  expect_fails("evaluate --model " + q(m3) + " --targets " + q(jointless) + " --cube-mm 40",
               jointless, "joint columns");
  expect_fails("evaluate --model " + q(m3) + " --targets " + q(cell_), cell_, "--cube-mm");
  expect_fails("evaluate --model " + q(m3) + " --targets " + q(cell_) + " --strategy 1", m3,
               "--strategy 3");
}

TEST_F(StrategyCli, HelpExplainsTheStrategies) {
  for (const char* command : {"register", "evaluate"}) {
    const CliResult r = run_vrreg(std::string(command) + " --help");
    EXPECT_EQ(r.status, 0);
    for (const char* words :
         {"--strategy 1", "--strategy 2", "--strategy 3", "Procedure 2", "--joint-norm"}) {
      EXPECT_NE(r.out.find(words), std::string::npos) << command << ": " << words;
    }
  }
}

}  // namespace
}  // namespace vrreg::testing
