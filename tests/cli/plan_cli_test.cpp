// SPDX-License-Identifier: Apache-2.0
// `vrreg plan` as a user runs it: a plan CSV in visiting order with joints, the d_min check and
// its --force, unreachable part points named, bad parts files named by file and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

const std::string kFourParts =
    "# four features, UR5 base frame\n"
    "point,robot_x_mm,robot_y_mm,robot_z_mm\n"
    "hole_A,420,-140,250\nhole_B,480,-140,250\npin_C,480,-60,260\npin_D,420,-60,240\n";

std::vector<std::string> data_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.front() != '#') lines.push_back(line);
  }
  return lines;
}

class PlanCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    parts_ = (dir_ / "parts.csv").string();
    plan_ = (dir_ / "plan.csv").string();
    write_text(parts_, kFourParts);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
  std::string parts_;
  std::string plan_;
};

TEST_F(PlanCli, WritesAPlanInVisitingOrderAndSummarisesInMillimetres) {
  const CliResult r =
      run_vrreg("plan --parts '" + parts_ + "' --halfwidth-mm 10 --spacing-mm 5 --robot ur5 -o '" +
                plan_ + "'");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("d_min = 4.330 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sigma_noise = 0.114 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("12.500 mm covered"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("plan written to"), std::string::npos);
  const std::string text = read_text(plan_);
  EXPECT_TRUE(text.starts_with("# vrreg plan")) << text.substr(0, 200);
  EXPECT_NE(text.find("# tool_mm: 0.000 0.000 60.000"), std::string::npos);
  EXPECT_NE(text.find("# spacing_mm: 5.000"), std::string::npos);
  const std::vector<std::string> lines = data_lines(text);
  ASSERT_EQ(lines.size(), 1u + 4u * 217u);
  EXPECT_EQ(lines[0],
            "point,role,part,robot_x_mm,robot_y_mm,robot_z_mm,config,q1_rad,q2_rad,q3_rad,"
            "q4_rad,q5_rad,q6_rad");
  int targets = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].find(",target,") != std::string::npos) ++targets;
  }
  EXPECT_EQ(targets, 4);
  EXPECT_NE(text.find("\nhole_A,target,hole_A,420,-140,250,"), std::string::npos);
}

TEST_F(PlanCli, JsonSummary) {
  const CliResult r = run_vrreg("plan --json --parts '" + parts_ +
                                "' --halfwidth-mm 7.5 --spacing-mm 5 --robot ur5 --norm linf");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["nodes_per_axis"], 4);
  EXPECT_EQ(j["n_fiducials_per_part"], 64);
  EXPECT_EQ(j["n_locations"], 4 * 65);
  EXPECT_NEAR(j["d_min_mm"].get<double>(), 4.330127, 1e-6);
  EXPECT_NEAR(j["sigma_noise_mm"].get<double>(), 0.114, 1e-12);
  EXPECT_TRUE(j["sigma_noise_default"].get<bool>());
  EXPECT_TRUE(j["dmin_ok"].get<bool>());
  EXPECT_EQ(j["norm"], "linf");
  EXPECT_EQ(j["parts"].size(), 4u);
  EXPECT_EQ(j["visit_order"].size(), 4u);
  EXPECT_LE(j["between_cubes_mm"].get<double>(),
            j["input_order_between_cubes_mm"].get<double>() + 1e-9);
  EXPECT_TRUE(j["output"].is_null());
  EXPECT_FALSE(std::filesystem::exists(plan_));
}

TEST_F(PlanCli, DminBelowTheNoiseLimitFailsUnlessForced) {
  const std::string args = "plan --parts '" + parts_ +
                           "' --halfwidth-mm 2 --spacing-mm 1 --sigma-noise-mm 0.5 --robot ur5 "
                           "-o '" +
                           plan_ + "'";
  const CliResult r = run_vrreg(args);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("d_min = 0.866 mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2.5 * sigma_noise = 1.250 mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(plan_));
  const CliResult forced = run_vrreg(args + " --force");
  ASSERT_EQ(forced.status, 0) << forced.err;
  EXPECT_NE(forced.out.find("FAILED (forced)"), std::string::npos) << forced.out;
  EXPECT_NE(read_text(plan_).find("FAILED, forced"), std::string::npos);
}

TEST_F(PlanCli, UnreachablePartPointIsNamedAndNothingWritten) {
  write_text(parts_, kFourParts + "far,1500,0,250\n");
  const CliResult r =
      run_vrreg("plan --parts '" + parts_ + "' --halfwidth-mm 10 --spacing-mm 5 --robot ur5 -o '" +
                plan_ + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("far (unreachable"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(plan_));
}

TEST_F(PlanCli, Lwr4WithTestBedDefaults) {
  write_text(parts_, "point,robot_x_m,robot_y_m,robot_z_m\nA,0.48,0.22,0.30\nB,0.54,0.22,0.30\n");
  const CliResult r =
      run_vrreg("plan --json --parts '" + parts_ +
                "' --halfwidth-mm 7.5 --spacing-mm 5 --robot lwr4 -o '" + plan_ + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["psi_deg"].get<double>(), -15.0, 1e-9);
  EXPECT_NEAR(j["sigma_noise_mm"].get<double>(), 0.077, 1e-12);
  EXPECT_NE(data_lines(read_text(plan_))[0].find(",q7_rad"), std::string::npos);
}

TEST_F(PlanCli, BadInputIsOneLineNamingTheProblem) {
  write_text(parts_, "point,robot_x_mm,robot_y_mm,robot_z_mm\nP,1,2\n");
  CliResult r =
      run_vrreg("plan --parts '" + parts_ + "' --halfwidth-mm 10 --spacing-mm 5 --robot ur5");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(parts_ + ":2: expected 4 fields"), std::string::npos) << r.err;
  write_text(parts_, kFourParts);
  r = run_vrreg("plan --parts '" + parts_ +
                "' --halfwidth-mm 10 --spacing-mm 5 --robot ur5 --psi-deg 10");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--psi-deg"), std::string::npos) << r.err;
  r = run_vrreg("plan --parts '" + parts_ +
                "' --halfwidth-mm 10 --spacing-mm 5 --robot ur5 --home-deg 1 2 3");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("6 joints, got 3"), std::string::npos) << r.err;
  r = run_vrreg("plan --parts '" + parts_ + "' --halfwidth-mm 10 --spacing-mm 0 --robot ur5");
  EXPECT_EQ(r.status, 2) << r.err;  // usage: not a positive number
  r = run_vrreg("plan --parts '" + parts_ + "' --halfwidth-mm 10 --spacing-mm 5 --robot nosuchbot");
  EXPECT_EQ(r.status, 1);
}


TEST_F(PlanCli, ApproachFromWritesViaRowsTheSimulatorAndTheProgramFollow) {
  write_text(parts_, "point,robot_x_mm,robot_y_mm,robot_z_mm\nhole_A,420,-140,250\n");
  const std::string program = (dir_ / "program.csv").string();
  const CliResult r = run_vrreg("plan --parts '" + parts_ +
                                "' --halfwidth-mm 5 --spacing-mm 5 --robot ur5 --approach-from "
                                "+,-,+,+,+,+ --approach-offset-deg 3 --export csv --program '" +
                                program + "' -o '" + plan_ + "'");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("every joint arrives from + - + + + +"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("a via point 3.000 deg before each of 65 locations"), std::string::npos)
      << r.out;
  const std::vector<std::string> lines = data_lines(read_text(plan_));
  ASSERT_EQ(lines.size(), 1u + 2u * 65u);  // a via row before every location
  for (std::size_t i = 1; i < lines.size(); i += 2) {
    const std::string point = lines[i].substr(0, lines[i].find(','));
    EXPECT_TRUE(lines[i].starts_with(point + ",via,hole_A,")) << lines[i];
    EXPECT_TRUE(lines[i + 1].starts_with(point + ",")) << lines[i + 1];
    EXPECT_EQ(lines[i + 1].find(",via,"), std::string::npos) << lines[i + 1];
  }
  // The program: via (0 readings) then the location, in the plan's order.
  const std::vector<std::string> rows = data_lines(read_text(program));
  ASSERT_EQ(rows.size(), 1u + 2u * 65u);
  EXPECT_NE(rows[1].find(",via,"), std::string::npos) << rows[1];
  EXPECT_TRUE(rows[1].ends_with(",0")) << rows[1];
  EXPECT_TRUE(rows[2].ends_with(",12")) << rows[2];
  // The simulator goes through the via points: the measurement CSV names where each row came from.
  const std::string measured = (dir_ / "measured.csv").string();
  const CliResult sim = run_vrreg("simulate ur5 --plan '" + plan_ + "' -o '" + measured + "'");
  ASSERT_EQ(sim.status, 0) << sim.err;
  EXPECT_NE(sim.out.find("65 locations"), std::string::npos) << sim.out;
  EXPECT_NE(read_text(measured).find(",from_q1_rad,"), std::string::npos);
  // Without the option: no via rows, no from_q columns.
  ASSERT_EQ(run_vrreg("plan --parts '" + parts_ +
                      "' --halfwidth-mm 5 --spacing-mm 5 --robot ur5 -o '" + plan_ + "'")
                .status,
            0);
  EXPECT_EQ(read_text(plan_).find(",via,"), std::string::npos);
  ASSERT_EQ(run_vrreg("simulate ur5 --plan '" + plan_ + "' -o '" + measured + "'").status, 0);
  EXPECT_EQ(read_text(measured).find("from_q"), std::string::npos);
  // Bad directions: one line naming the option.
  const CliResult bad = run_vrreg("plan --parts '" + parts_ +
                                  "' --halfwidth-mm 5 --spacing-mm 5 --robot ur5 "
                                  "--approach-from +,-");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("--approach-from: robot 'ur5' has 6 joints, got 2"), std::string::npos)
      << bad.err;
}

}  // namespace
}  // namespace vrreg::testing
