// SPDX-License-Identifier: Apache-2.0
// `vrreg fk` and `vrreg ik` as a user runs them: every IK solution maps back through fk, errors
// are one line with exit status 1.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "robot_files.hpp"

namespace {

struct CliRun {
  int status = -1;
  std::string out;  // stdout and stderr
};

// stdout and stderr together, or stdout alone (`with_stderr` false: stderr is dropped).
CliRun run(const std::string& args, bool with_stderr = true) {
  const std::string command =
      std::string(VRREG_CLI_PATH) + " " + args + (with_stderr ? " 2>&1" : " 2>/dev/null");
  CliRun r;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.out.append(buffer.data(), n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

// Runs "COMMAND --json REST" (the flag goes first: REST may end in "-- joint values").
nlohmann::json run_json(const std::string& args) {
  const std::size_t space = args.find(' ');
  const CliRun r = run(args.substr(0, space) + " --json" + args.substr(space));
  EXPECT_EQ(r.status, 0) << args << "\n" << r.out;
  return nlohmann::json::parse(r.out);
}

std::string numbers(const nlohmann::json& array) {
  std::string s;
  char buf[64];
  for (const auto& v : array) {
    std::snprintf(buf, sizeof buf, " %.17g", v.get<double>());
    s += buf;
  }
  return s;
}

// Runs ik, then fk on every solution, and checks the pose comes back.
void expect_round_trip(const std::string& robot, const std::string& pose_args,
                       std::size_t expected_solutions) {
  const nlohmann::json ik = run_json("ik " + robot + " " + pose_args);
  ASSERT_EQ(ik["status"], "ok") << ik.dump(2);
  // expected_solutions 0: any number but none.
  if (expected_solutions > 0) {
    ASSERT_EQ(ik["solutions"].size(), expected_solutions) << ik.dump(2);
  }
  ASSERT_FALSE(ik["solutions"].empty()) << ik.dump(2);
  const nlohmann::json& target = ik["target"];
  for (const auto& solution : ik["solutions"]) {
    ASSERT_TRUE(solution.contains("config"));
    const nlohmann::json fk = run_json("fk " + robot + " -- " + numbers(solution["q_rad"]));
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(fk["xyz_mm"][i].get<double>(), target["xyz_mm"][i].get<double>(), 1e-6);
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(fk["rotation"][i][j].get<double>(), target["rotation"][i][j].get<double>(),
                    1e-9);
      }
    }
    EXPECT_EQ(fk["config"], solution["config"]);
    if (fk.contains("psi_deg")) {
      EXPECT_NEAR(fk["psi_deg"].get<double>(), ik["psi_deg"].get<double>(), 1e-6);
    }
  }
}

TEST(KinematicsCli, Ur5IkListsEightSolutionsThatFkMapsBack) {
  expect_round_trip("ur5", "--xyz-mm -498.46658 -430.327486 180.045119 --rpy-deg 172.9 7.05 74.56",
                    8);
}

TEST(KinematicsCli, Lwr4IkListsEveryConfigurationAtAnArmAngle) {
  // At psi = 94.4 deg all 8 configurations of this pose are within the LWR 4+ limits, at
  // psi = 100 deg four are, at psi = -80 deg none.
  const std::string pose =
      "--xyz-mm 46.077925 -204.444075 934.150094 --rpy-deg 81.449652 5.544838 90.544813";
  expect_round_trip("lwr4", pose + " --psi-deg 94.4", 8);
  expect_round_trip("lwr4", pose + " --psi-deg 100", 4);
  const CliRun refused = run("ik --json lwr4 " + pose + " --psi-deg -80", false);
  EXPECT_EQ(refused.status, 3);
  const nlohmann::json none = nlohmann::json::parse(refused.out);
  EXPECT_EQ(none["status"], "outside-limits");
  EXPECT_EQ(none["n_outside_limits"], 8);
}

TEST(KinematicsCli, ToolOffsetMovesTheTcp) {
  const nlohmann::json a = run_json("fk ur10 --deg 10 -70 80 -100 -90 0");
  const nlohmann::json b = run_json("fk ur10 --deg 10 -70 80 -100 -90 0 --tool-mm 0 0 100");
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = b["xyz_mm"][i].get<double>() - a["xyz_mm"][i].get<double>();
    d2 += d * d;
  }
  EXPECT_NEAR(std::sqrt(d2), 100.0, 1e-9);
  const nlohmann::json ik = run_json("ik ur10 --tool-mm 0 0 100 --xyz-mm " + numbers(b["xyz_mm"]) +
                                     " --rpy-deg " + numbers(b["rpy_deg"]));
  bool found = false;
  for (const auto& s : ik["solutions"]) {
    found = found || std::abs(s["q_deg"][0].get<double>() - 10.0) +
                             std::abs(s["q_deg"][1].get<double>() + 70.0) <
                         1e-6;
  }
  EXPECT_TRUE(found) << ik.dump(2);
}

TEST(KinematicsCli, HumanOutputStatesUnits) {
  const CliRun fk = run("fk ur5 0.1 -1.2 1.3 -0.4 1.5 0.2");
  EXPECT_EQ(fk.status, 0);
  EXPECT_NE(fk.out.find("position [mm]"), std::string::npos) << fk.out;
  EXPECT_NE(fk.out.find("vrreg ik ur5 --xyz-mm"), std::string::npos) << fk.out;
  const CliRun ik = run("ik lwr4 --xyz-mm 400 100 600 --rpy-deg 180 20 0 --psi-deg 45");
  EXPECT_EQ(ik.status, 0);
  EXPECT_NE(ik.out.find("joint values in deg"), std::string::npos) << ik.out;
  EXPECT_NE(ik.out.find("GC="), std::string::npos) << ik.out;
  EXPECT_NE(ik.out.find("feasible psi"), std::string::npos) << ik.out;
}

TEST(KinematicsCli, ControllerStyleSingleSolution) {
  const nlohmann::json ik = run_json(
      "ik ur5 --xyz-mm -498.46658 -430.327486 180.045119 --rpy-deg 172.9 7.05 74.56 "
      "--current-deg 29 -61 91 -119 -81 44");
  ASSERT_EQ(ik["solutions"].size(), 1u);
  EXPECT_EQ(ik["solutions"][0]["config"], "shoulder-left/elbow-up/wrist-flip");
}

TEST(KinematicsCli, NoSolutionIsAnAnswerWithExitStatusThree) {
  const CliRun json = run("ik --json ur5 --xyz-mm 3000 0 0 --rpy-deg 0 0 0", false);
  EXPECT_EQ(json.status, 3) << json.out;
  const nlohmann::json ik = nlohmann::json::parse(json.out);
  EXPECT_EQ(ik["status"], "unreachable");
  EXPECT_TRUE(ik["solutions"].empty());
  EXPECT_FALSE(ik["message"].get<std::string>().empty());
  const CliRun human = run("ik ur5 --xyz-mm 3000 0 0 --rpy-deg 0 0 0");
  EXPECT_EQ(human.status, 3) << human.out;
  EXPECT_NE(human.out.find("  no solution (unreachable): "), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("\nvrreg: ik: no solution (unreachable): "), std::string::npos)
      << human.out;
}

// fk's own "back to joints" line at the UR wrist singularity (q5 = 0) inverts.
TEST(KinematicsCli, IkInvertsFkAtTheWristSingularity) {
  const CliRun fk = run("fk ur5 -- 1.33 -0.31 0.81 -1.63 0 1.06");
  ASSERT_EQ(fk.status, 0) << fk.out;
  const std::string marker = "back to joints:   vrreg ";
  const std::size_t at = fk.out.find(marker);
  ASSERT_NE(at, std::string::npos) << fk.out;
  const std::string command =
      fk.out.substr(at + marker.size(), fk.out.find('\n', at) - at - marker.size());
  const CliRun ik = run(command);
  EXPECT_EQ(ik.status, 0) << command << "\n" << ik.out;
  EXPECT_NE(ik.out.find("singular: wrist"), std::string::npos) << ik.out;
  expect_round_trip("ur5", command.substr(command.find("--xyz-mm")), 0);
  // The same pose rounded to 6 decimals: q6 now follows the rounding, which puts the wrist out of
  // reach; the refusal says why.
  const CliRun rounded =
      run("ik ur5 --xyz-mm -13.100067 -856.153506 -9.629098 --rpy-deg 90 4.010705 76.203387");
  EXPECT_EQ(rounded.status, 3) << rounded.out;
  EXPECT_NE(rounded.out.find("the wrist is nearly singular"), std::string::npos) << rounded.out;
}

// A URDF robot with a prismatic joint: fk, then every ik solution back through fk; the slide is
// shown in mm.
TEST(KinematicsCli, UrdfArmOnALinearAxis) {
  const std::string rail = std::string(VRREG_TEST_DATA_DIR) + "/urdf/ur5_on_rail.urdf";
  const nlohmann::json fk = run_json("fk " + rail + " -- 0.7 0.3 -1.2 1.4 -1.7 -1.5 0.2");
  EXPECT_NEAR(fk["q_deg"][0].get<double>(), 700.0, 1e-9);
  expect_round_trip(rail,
                    "--xyz-mm" + numbers(fk["xyz_mm"]) + " --rpy-deg" + numbers(fk["rpy_deg"]), 0);
  const CliRun human = run("fk --deg " + rail + " -- 700 0 0 0 0 0 0");
  EXPECT_EQ(human.status, 0) << human.out;
  EXPECT_NE(human.out.find("(q1 in mm: prismatic)"), std::string::npos) << human.out;
}

TEST(KinematicsCli, BadInputIsOneLineAndExitStatusOne) {
  const char* cases[][2] = {
      {"fk ur5 1 2 3", "has 6 joints, got 3"},
      {"fk ur7 1 2 3 4 5 6", "unknown robot 'ur7'"},
      {"fk ur5 1 2 3 4 5 nan", "not a finite number"},
      {"ik ur5 --xyz-mm 300 0 300 --rotation 1 0 0 0 2 0 0 0 1", "not a rotation"},
      {"ik ur5 --xyz-mm 300 0 300 --rpy-deg 0 0 0 --psi-deg 10", "--psi-deg applies to 7-joint"},
      {"ik lwr4 --xyz-mm 300 0 300 --rpy-deg 0 0 inf", "not a finite number"},
  };
  for (const auto& c : cases) {
    const CliRun r = run(c[0]);
    EXPECT_EQ(r.status, 1) << c[0] << "\n" << r.out;
    EXPECT_EQ(r.out.rfind("vrreg: error: ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find(c[1]), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << "one line: " << r.out;
  }
}

TEST(KinematicsCli, RobotFileAndItsErrors) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vrreg_kin_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string good = (dir / "arm.yaml").string();
  std::ofstream(good) << vrreg::testing::kUr5RobotYaml;
  const nlohmann::json from_file = run_json("fk " + good + " 0.1 -1.2 1.3 -0.4 1.5 0.2");
  const nlohmann::json builtin = run_json("fk ur5 0.1 -1.2 1.3 -0.4 1.5 0.2");
  EXPECT_EQ(from_file["robot"], "my-ur5");
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(from_file["xyz_mm"][i].get<double>(), builtin["xyz_mm"][i].get<double>(), 1e-9);
  }
  expect_round_trip(good, "--xyz-mm 300 -200 400 --rpy-deg 170 10 30", 8);
  const std::string bad = (dir / "bad.yaml").string();
  std::ofstream(bad) << "dh:\n  - {a_m: 0, alpha_deg: 90}\n";
  const CliRun r = run("fk " + bad + " 0");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find(bad + ":2: dh[0]: missing d_m or d_mm"), std::string::npos) << r.out;
  std::filesystem::remove_all(dir);
}

}  // namespace
