// SPDX-License-Identifier: Apache-2.0
// Adaptive planning on the command line: vrreg plan-next -> vrreg simulate ur5 --plan ->
// vrreg plan-next --measured, twice; the plan file is the one `vrreg plan` writes.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "vrreg_test.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kNextParts =
    "point,robot_x_mm,robot_y_mm,robot_z_mm\n"
    "hole_A,420,-140,250\nhole_B,480,-140,250\npin_C,480,-60,260\n";

class PlanNextCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    write_text(dir_ / "parts.csv", kNextParts);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string p(const char* name) const { return "'" + (dir_ / name).string() + "'"; }
  std::string plan_next(const std::string& extra) const {
    return "plan-next --parts " + p("parts.csv") + " --robot ur5 --goal-sd-mm 0.05 --batch 6 " +
           "--budget 30 " + extra;
  }
  // Data rows (no comments, no header) of a CSV file.
  std::string data_rows(const char* name) const {
    const std::string text = read_text(dir_ / name);
    std::string out;
    bool header = true;
    std::size_t start = 0;
    while (start < text.size()) {
      const std::size_t end = text.find('\n', start);
      const std::string line = text.substr(start, end - start + 1);
      start = end == std::string::npos ? text.size() : end + 1;
      if (line.starts_with("#")) continue;
      if (header) {
        header = false;
        continue;
      }
      out += line;
    }
    return out;
  }
  fs::path dir_;
};

TEST_F(PlanNextCli, PlanSimulatePlanAgainTwice) {
  // First batch: nothing measured, a space-filling design of 12 (the model's minimum).
  const CliResult first = run_vrreg(plan_next("-o " + p("b1.csv")));
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find("12 locations (space-filling)"), std::string::npos) << first.out;
  EXPECT_NE(first.out.find("CONTINUE"), std::string::npos);
  const std::string b1 = read_text(dir_ / "b1.csv");
  EXPECT_NE(b1.find("point,role,part,robot_x_mm,robot_y_mm,robot_z_mm,config,q1_rad"),
            std::string::npos);
  ASSERT_EQ(run_vrreg("simulate ur5 --plan " + p("b1.csv") + " --seed 3 -o " + p("all.csv")).status,
            0);

  // Second batch: a model fitted on the 12, a greedy batch of 6 named after them.
  const CliResult second =
      run_vrreg(plan_next("--measured " + p("all.csv") + " -o " + p("b2.csv") + " --json"));
  ASSERT_EQ(second.status, 0) << second.err;
  const json s = json::parse(second.out);
  EXPECT_EQ(s["decision"], "continue");
  EXPECT_EQ(s["n_measured"], 12);
  EXPECT_EQ(s["n_planned"], 6);
  EXPECT_FALSE(s["space_filling"].get<bool>());
  EXPECT_LT(s["predicted_sd_after_mm"].get<double>(), s["predicted_sd_now_mm"].get<double>());
  EXPECT_GT(s["predicted_sd_now_mm"].get<double>(), 0.05);
  EXPECT_NE(read_text(dir_ / "b2.csv").find("\nn13,fiducial,"), std::string::npos);
  ASSERT_EQ(run_vrreg("simulate ur5 --plan " + p("b2.csv") + " --seed 3 -o " + p("m2.csv")).status,
            0);
  write_text(dir_ / "all.csv", read_text(dir_ / "all.csv") + data_rows("m2.csv"));

  // Third call: 18 measured; the same predicted sd printed as the plan file's comment says.
  const CliResult third = run_vrreg(plan_next("--measured " + p("all.csv") + " -o " + p("b3.csv") +
                                              " --export urscript --program " + p("b3.script")));
  ASSERT_EQ(third.status, 0) << third.err;
  EXPECT_NE(third.out.find("measured fiducials: 18"), std::string::npos) << third.out;
  const std::string b3 = read_text(dir_ / "b3.csv");
  EXPECT_NE(b3.find("# measured fiducials: 18"), std::string::npos);
  EXPECT_NE(b3.find("\nn19,fiducial,"), std::string::npos);
  // The program visits the locations in the order written.
  const std::string script = read_text(dir_ / "b3.script");
  std::size_t last = 0;
  for (int k = 19; k <= 24; ++k) {
    const std::size_t at = script.find("n" + std::to_string(k));
    if (at == std::string::npos) continue;  // not every batch is 6 long near a stop
    EXPECT_GT(at, last) << "n" << k;
    last = at;
  }
  EXPECT_GT(last, 0u);

  // The budget spent: STOP, and no plan written.
  const CliResult stop = run_vrreg("plan-next --parts " + p("parts.csv") +
                                   " --robot ur5 --goal-sd-mm 0.05 --budget 18 --measured " +
                                   p("all.csv") + " -o " + p("b4.csv"));
  ASSERT_EQ(stop.status, 0) << stop.err;
  EXPECT_NE(stop.out.find("STOP: the budget is spent"), std::string::npos) << stop.out;
  EXPECT_FALSE(fs::exists(dir_ / "b4.csv"));
}

// What a closed loop measured: fiducials at STOP, the predicted sd STOP printed, the kriging
// registration's RMS_T at the part points, and Procedure 1's (10 mm cubes of 5 mm spacing,
// octuplet correction) in the same cell.
struct ClosedLoop {
  int n_fiducials = 0;
  int n_procedure1 = 0;
  double predicted_mm = 0.0;
  double adaptive_mm = 0.0;
  double procedure1_mm = 0.0;
  std::string predicted_by{};
  std::string reason{};
};

class PlanNextLoop : public PlanNextCli {
 protected:
  // plan-next -> simulate -> plan-next until STOP on the test bed `robot`, 27 part points on the
  // grid xs x ys x zs (mm), then both registrations evaluated at the part points (targets of
  // the same seed).
  ClosedLoop loop(const std::string& robot, const std::array<int, 3>& xs,
                  const std::array<int, 3>& ys, const std::array<int, 3>& zs,
                  const std::string& goal, int seed, const std::string& interpolation = "kriging") {
    std::string parts = "point,robot_x_mm,robot_y_mm,robot_z_mm\n";
    int k = 0;
    for (const int x : xs) {
      for (const int y : ys) {
        for (const int z : zs) {
          parts += "P" + std::to_string(++k) + "," + std::to_string(x) + "," + std::to_string(y) +
                   "," + std::to_string(z) + "\n";
        }
      }
    }
    write_text(dir_ / "parts.csv", parts);
    const std::string s = " --seed " + std::to_string(seed);
    ClosedLoop out;
    const CliResult proc1 =
        run_vrreg("plan --parts " + p("parts.csv") + " --halfwidth-mm 10 --spacing-mm 5 --robot " +
                  robot + " --json -o " + p("proc1.csv"));
    EXPECT_EQ(proc1.status, 0) << proc1.err;
    if (proc1.status != 0) return out;
    out.n_procedure1 = 27 * json::parse(proc1.out)["n_fiducials_per_part"].get<int>();
    EXPECT_EQ(
        run_vrreg("simulate " + robot + " --plan " + p("proc1.csv") + s + " -o " + p("p1m.csv"))
            .status,
        0);
    EXPECT_EQ(run_vrreg("simulate " + robot + " --plan " + p("proc1.csv") + " --only target" + s +
                        " -o " + p("targets.csv"))
                  .status,
              0);
    json last;
    bool measured = false;
    for (int round = 1; round <= 20; ++round) {
      const std::string batch = "b" + std::to_string(round) + ".csv";
      const CliResult next =
          run_vrreg("plan-next --parts " + p("parts.csv") + " --robot " + robot + " " + goal +
                    " --batch 8 --budget 300 --interpolation " + interpolation + " --json -o " +
                    p(batch.c_str()) +
                    (measured ? " --measured " + p("all.csv") : std::string()));
      EXPECT_EQ(next.status, 0) << next.err;
      if (next.status != 0) return out;
      last = json::parse(next.out);
      if (last["decision"] == "stop") break;
      EXPECT_EQ(
          run_vrreg("simulate " + robot + " --plan " + p(batch.c_str()) + s + " -o " + p("m.csv"))
              .status,
          0);
      write_text(dir_ / "all.csv", measured ? read_text(dir_ / "all.csv") + data_rows("m.csv")
                                            : read_text(dir_ / "m.csv"));
      measured = true;
    }
    EXPECT_EQ(last["decision"], "stop");
    if (last["decision"] != "stop") return out;
    out.n_fiducials = last["n_measured"].get<int>();
    out.predicted_mm = last["predicted_sd_now_mm"].get<double>();
    out.predicted_by = last["predicted_by"].get<std::string>();
    out.reason = last["reason"].get<std::string>();
    auto rms_t_mm = [&](const char* fiducials, const std::string& register_flags) {
      const CliResult reg = run_vrreg("register --fiducials " + p(fiducials) + register_flags +
                                      " -o " + p("model.json"));
      EXPECT_EQ(reg.status, 0) << reg.err;
      const CliResult eval = run_vrreg("evaluate --model " + p("model.json") + " --targets " +
                                       p("targets.csv") + " --json");
      EXPECT_EQ(eval.status, 0) << eval.err;
      return json::parse(eval.out)["cor_rms_t_mm"].get<double>();
    };
    out.adaptive_mm =
        rms_t_mm("all.csv", " --interpolation " + interpolation + " --robot " + robot);
    out.procedure1_mm = rms_t_mm("p1m.csv", "");
    return out;
  }
};

// The closed loop on the simulated UR5 (seed 3), 27 part points 50 x 50 x 35 mm apart, against
// Procedure 1's plan measured in the same cell. docs/adaptive.md has the numbers of seeds 3-5.
TEST_F(PlanNextLoop, ClosedLoopStopsWithFewFiducialsAndAnHonestPrediction) {
  if (sanitized()) GTEST_SKIP() << "a dozen simulate and plan runs";
  const ClosedLoop r =
      loop("ur5", {400, 450, 500}, {-150, -100, -50}, {220, 255, 290}, "--goal-sd-mm 0.05", 3);
  ASSERT_GT(r.n_fiducials, 0);
  EXPECT_EQ(r.n_procedure1, 27 * 216);  // 27 cubes of 6^3 fiducials
  EXPECT_LE(4 * r.n_fiducials, r.n_procedure1) << r.n_fiducials;
  // Seed 3: 76 fiducials, 0.116 mm measured against 0.117 mm predicted; Procedure 1's 5832
  // fiducials 0.132 mm.
  EXPECT_NEAR(r.adaptive_mm / r.predicted_mm, 1.0, 0.2)
      << r.adaptive_mm << " vs " << r.predicted_mm;
  EXPECT_LE(r.adaptive_mm, 1.1 * r.procedure1_mm) << r.adaptive_mm << " vs " << r.procedure1_mm;
}

// The same loop on the simulated KUKA LWR 4+ (seed 3; 7 joints, arm angle fixed), 27 part points
// 50 x 50 x 35 mm apart. The LWR test bed reads each location once, so the loop runs with a
// goal in mm (the noise floor is unknown without repeats) and stops on the 1 % rule.
TEST_F(PlanNextLoop, ClosedLoopOnTheLwr4) {
  if (sanitized()) GTEST_SKIP() << "a dozen simulate and plan runs";
  const ClosedLoop r =
      loop("lwr4", {450, 500, 550}, {200, 250, 300}, {265, 300, 335}, "--goal-sd-mm 0.03", 3);
  ASSERT_GT(r.n_fiducials, 0);
  EXPECT_EQ(r.n_procedure1, 27 * 216);
  // Seed 3: 68 fiducials (1.2 % of Procedure 1's 5832), RMS_T 0.135 mm against Procedure 1's
  // 0.148 mm; predicted 0.112 mm, measured / predicted 1.20 (the worst of seeds 3-5: 1.20,
  // 1.09, 1.02; the prediction leans optimistic on the LWR).
  EXPECT_LE(4 * r.n_fiducials, r.n_procedure1) << r.n_fiducials;
  EXPECT_LE(r.adaptive_mm, 1.1 * r.procedure1_mm) << r.adaptive_mm << " vs " << r.procedure1_mm;
  EXPECT_GT(r.adaptive_mm / r.predicted_mm, 0.8) << r.adaptive_mm << " vs " << r.predicted_mm;
  EXPECT_LT(r.adaptive_mm / r.predicted_mm, 1.3) << r.adaptive_mm << " vs " << r.predicted_mm;
}

// The loop correcting with the joint-space model (--interpolation joint): the goal is judged on
// that model's predicted sd at the parts once it can be fitted (kriging's before), and the loop
// stops when it reaches the goal, with an honest prediction and fewer fiducials than the
// kriging loop needs to level off.
TEST_F(PlanNextLoop, ClosedLoopWithTheJointModelStopsOnItsOwnSd) {
  if (sanitized()) GTEST_SKIP() << "a dozen simulate, plan and joint-model runs";
  const ClosedLoop r = loop("ur5", {400, 450, 500}, {-150, -100, -50}, {220, 255, 290},
                            "--goal-sd-mm 0.11", 3, "joint");
  ASSERT_GT(r.n_fiducials, 0);
  EXPECT_EQ(r.predicted_by, "joint");
  EXPECT_EQ(r.reason, "the goal is reached");
  EXPECT_LE(r.predicted_mm, 0.11);
  EXPECT_NEAR(r.adaptive_mm / r.predicted_mm, 1.0, 0.2)
      << r.adaptive_mm << " vs " << r.predicted_mm;
  // Seed 3: 84 fiducials, 0.102 mm measured against 0.099 mm predicted by the joint model
  // (kriging's loop: 76 fiducials, 0.116 mm; Procedure 1's 5832 fiducials: 0.132 mm).
  EXPECT_LE(r.adaptive_mm, r.procedure1_mm) << r.adaptive_mm << " vs " << r.procedure1_mm;
  std::printf("joint loop, UR5 seed 3: %d fiducials, predicted %.4f mm, measured %.4f mm, "
              "Procedure 1 %.4f mm\n",
              r.n_fiducials, r.predicted_mm, r.adaptive_mm, r.procedure1_mm);
}

// --interpolation joint on measurements that can never carry the joint-space model (no joint
// columns; a robot with another joint count) is refused at once, naming the file, not answered
// with kriging's sd batch after batch.
TEST_F(PlanNextCli, JointInterpolationWithoutTheJointsIsRefused) {
  ASSERT_EQ(run_vrreg(plan_next("-o " + p("b1.csv"))).status, 0);
  ASSERT_EQ(run_vrreg("simulate ur5 --plan " + p("b1.csv") + " --seed 3 -o " + p("m1.csv")).status,
            0);
  // m1.csv without its joint columns (q1_rad ..).
  std::string without;
  const std::string text = read_text(dir_ / "m1.csv");
  std::size_t start = 0;
  bool header = true;
  std::vector<bool> keep;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end - start);
    start = end == std::string::npos ? text.size() : end + 1;
    if (line.empty() || line.starts_with("#")) continue;
    std::vector<std::string> cells;
    for (std::size_t at = 0;;) {
      const std::size_t comma = line.find(',', at);
      cells.push_back(line.substr(at, comma - at));
      if (comma == std::string::npos) break;
      at = comma + 1;
    }
    if (header) {
      for (const std::string& name : cells) keep.push_back(!name.starts_with("q"));
      header = false;
    }
    std::string out;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (keep[c]) out += (out.empty() ? "" : ",") + cells[c];
    }
    without += out + "\n";
  }
  write_text(dir_ / "nojoints.csv", without);
  const CliResult no_joints =
      run_vrreg(plan_next("--interpolation joint --measured " + p("nojoints.csv")));
  EXPECT_NE(no_joints.status, 0);
  EXPECT_NE(no_joints.err.find("nojoints.csv: joint interpolation needs the fiducials' joint "
                               "angles, 6 per row"),
            std::string::npos)
      << no_joints.err;
  const CliResult other_robot =
      run_vrreg("plan-next --parts " + p("parts.csv") + " --robot lwr4 --goal-sd-mm 0.05 " +
                "--interpolation joint --measured " + p("m1.csv"));
  EXPECT_NE(other_robot.status, 0);
  EXPECT_NE(other_robot.err.find("7 per row"), std::string::npos) << other_robot.err;
  // The same file with kriging, and with its joints, is planned as before.
  EXPECT_EQ(run_vrreg(plan_next("--measured " + p("nojoints.csv"))).status, 0);
  EXPECT_EQ(run_vrreg(plan_next("--interpolation joint --measured " + p("m1.csv"))).status, 0);
}

TEST_F(PlanNextCli, BadInputNamesTheProblem) {
  write_text(dir_ / "far.csv", "point,robot_x_mm,robot_y_mm,robot_z_mm\nfar,2000,0,200\n");
  const CliResult far =
      run_vrreg("plan-next --parts " + p("far.csv") + " --robot ur5 --goal-sd-mm 0.1");
  EXPECT_NE(far.status, 0);
  EXPECT_NE(far.err.find("far.csv:2"), std::string::npos) << far.err;
  write_text(dir_ / "bad.csv", "point,role,robot_x_mm\nx,fiducial,1\n");
  const CliResult bad = run_vrreg(plan_next("--measured " + p("bad.csv")));
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("bad.csv"), std::string::npos) << bad.err;
  EXPECT_NE(run_vrreg("plan-next --parts " + p("parts.csv") + " --robot ur5 --goal-sd-mm 0").status,
            0);
  // 14 fiducials on a line: the registration is undefined; the error names the file.
  std::string line =
      "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,"
      "sensor_z_mm\n";
  for (int k = 0; k < 14; ++k) {
    line += "f" + std::to_string(k) + ",fiducial," + std::to_string(400 + 10 * k) + ",-100,250," +
            std::to_string(10 * k) + ",0,2000\n";
  }
  write_text(dir_ / "line.csv", line);
  const CliResult collinear = run_vrreg(plan_next("--measured " + p("line.csv")));
  EXPECT_NE(collinear.status, 0);
  EXPECT_NE(collinear.err.find("plan next: "), std::string::npos) << collinear.err;
  EXPECT_NE(collinear.err.find("line.csv: "), std::string::npos) << collinear.err;
  EXPECT_NE(collinear.err.find("collinear"), std::string::npos) << collinear.err;
  // One goal, not both, not none.
  EXPECT_NE(run_vrreg(plan_next("--goal-floor-multiple 2")).status, 0);
  const CliResult none = run_vrreg("plan-next --parts " + p("parts.csv") + " --robot ur5");
  EXPECT_NE(none.status, 0);
  EXPECT_NE(none.err.find("--goal-floor-multiple"), std::string::npos) << none.err;
}

// The goal as a multiple of the noise floor sqrt(3 (sigma_rep^2 + sigma_opt^2 / K)): unknown
// before anything is measured (said, and the first batch planned anyway), then computed from the
// measured file's repeat readings (sigma_opt as `vrreg register` reports it, K = 12 readings).
// The plan rows carry the lattice values as written (400, not 399.99999999999994).
TEST_F(PlanNextCli, GoalAsAFloorMultipleAndLatticeRows) {
  const std::string next = "plan-next --parts " + p("parts.csv") +
                           " --robot ur5 --goal-floor-multiple 2 --sigma-rep-mm 0.05 --batch 6 ";
  const CliResult first = run_vrreg(next + "-o " + p("b1.csv"));
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find("goal 2 x the noise floor (not known yet: no repeat readings)"),
            std::string::npos)
      << first.out;
  EXPECT_NE(first.out.find("CONTINUE"), std::string::npos) << first.out;
  const std::string b1 = read_text(dir_ / "b1.csv");
  EXPECT_NE(b1.find("\nn1,fiducial,pin_C,400,-40,235,1,"), std::string::npos) << b1;
  EXPECT_EQ(b1.find("99999"), std::string::npos) << b1;
  EXPECT_EQ(b1.find("00000000"), std::string::npos) << b1;
  ASSERT_EQ(run_vrreg("simulate ur5 --plan " + p("b1.csv") + " --seed 3 -o " + p("m1.csv")).status,
            0);
  const CliResult reg =
      run_vrreg("register --fiducials " + p("m1.csv") + " --sigma-rep-mm 0.05 --json");
  ASSERT_EQ(reg.status, 0) << reg.err;
  const double sigma_opt_mm = json::parse(reg.out)["sigma_opt_mm"].get<double>();
  const double floor_mm = std::sqrt(3.0 * (0.05 * 0.05 + sigma_opt_mm * sigma_opt_mm / 12.0));

  const CliResult second = run_vrreg(next + "--measured " + p("m1.csv") + " --json");
  ASSERT_EQ(second.status, 0) << second.err;
  const json s = json::parse(second.out);
  EXPECT_NEAR(s["noise_floor_mm"].get<double>(), floor_mm, 1e-12 * floor_mm);
  EXPECT_NEAR(s["goal_sd_mm"].get<double>(), 2.0 * floor_mm, 1e-12 * floor_mm);
  // Seed 3: floor 0.092 mm, predicted 0.122 mm: below twice the floor, above the floor.
  EXPECT_EQ(s["decision"], "stop");
  EXPECT_EQ(s["reason"], "the goal is reached");
  const CliResult tighter = run_vrreg("plan-next --parts " + p("parts.csv") +
                                      " --robot ur5 --goal-floor-multiple 1 --sigma-rep-mm 0.05 "
                                      "--batch 6 --json --measured " +
                                      p("m1.csv"));
  ASSERT_EQ(tighter.status, 0) << tighter.err;
  EXPECT_EQ(json::parse(tighter.out)["decision"], "continue") << tighter.out;
}

// --volume: the part points are the box's lattice, the same batch as --parts with those points
// (named v1.. in the same order); a box inside out, or both inputs, are refused.
TEST_F(PlanNextCli, VolumeIsTheLatticeOfParts) {
  std::string lattice = "point,robot_x_mm,robot_y_mm,robot_z_mm\n";
  int k = 0;
  for (const int z : {230, 280}) {
    for (const int y : {-150, -100, -50}) {
      for (const int x : {400, 450, 500}) {
        lattice += "v" + std::to_string(++k) + "," + std::to_string(x) + "," + std::to_string(y) +
                   "," + std::to_string(z) + "\n";
      }
    }
  }
  write_text(dir_ / "lattice.csv", lattice);
  const std::string rest = " --robot ur5 --goal-sd-mm 0.05 --batch 6 --json -o ";
  const CliResult volume = run_vrreg("plan-next --volume 400,500,-150,-50,220,290" + rest +
                                     p("volume.csv"));
  ASSERT_EQ(volume.status, 0) << volume.err;
  const CliResult parts = run_vrreg("plan-next --parts " + p("lattice.csv") + rest + p("parts.csv"));
  ASSERT_EQ(parts.status, 0) << parts.err;
  EXPECT_EQ(json::parse(volume.out)["parts"].size(), 18u);
  EXPECT_EQ(read_text(dir_ / "volume.csv"), read_text(dir_ / "parts.csv"));
  EXPECT_EQ(volume.out, parts.out);
  const CliResult inside_out =
      run_vrreg("plan-next --volume 500,400,-150,-50,220,290 --robot ur5 --goal-sd-mm 0.05");
  EXPECT_NE(inside_out.status, 0);
  EXPECT_NE(inside_out.err.find("x range is empty"), std::string::npos) << inside_out.err;
  EXPECT_NE(run_vrreg("plan-next --volume 400,500,-150,-50,220,290 --parts " + p("lattice.csv") +
                      " --robot ur5 --goal-sd-mm 0.05")
                .status,
            0);
  const CliResult neither = run_vrreg("plan-next --robot ur5 --goal-sd-mm 0.05");
  EXPECT_NE(neither.status, 0);
  EXPECT_NE(neither.err.find("--volume"), std::string::npos) << neither.err;
}

// vrreg adaptive-study refuses what it cannot run before running anything (the study itself is
// AdaptiveStudy.QuickOnBothTestBeds in tests/experiments).
TEST(AdaptiveStudyCli, BadInputIsRefused) {
  const CliResult robot = run_vrreg("adaptive-study --robots ur10");
  EXPECT_NE(robot.status, 0);
  EXPECT_NE(robot.err.find("--robots"), std::string::npos) << robot.err;
  EXPECT_NE(run_vrreg("adaptive-study --quick --batch 8").status, 0);
  EXPECT_NE(run_vrreg("adaptive-study --seconds-per-move -1").status, 0);
  EXPECT_NE(run_vrreg("adaptive-study --goal-sd-mm 0").status, 0);
}

}  // namespace
}  // namespace vrreg::testing
