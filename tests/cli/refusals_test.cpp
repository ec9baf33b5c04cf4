// SPDX-License-Identifier: Apache-2.0
// Inputs at the edges of what the commands take: each is refused with one line naming the file
// (and line, or key) or the option, exit 1 or 2, no NaN in the message, nothing written, and no
// hang. A far part point, a part label a plan cannot hold, an output that cannot be written after
// another was made, a reproduce.json of the wrong shape, seeds at 2^64 - 1, a damaged joint-space
// model, joint interpolation without joints, an empty input name.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

int lines_of(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

void expect_refused(const CliResult& r, const std::string& where, const std::string& words) {
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_EQ(lines_of(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(where), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
}

class Refusals : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    parts_ = dir_ / "parts.csv";
    plan_ = dir_ / "plan.csv";
    program_ = dir_ / "p.script";
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliResult plan(const std::string& robot, const std::string& extra = "") const {
    return run_vrreg("plan --parts " + shell_quoted(parts_) +
                     " --halfwidth-mm 10 --spacing-mm 20 --robot " + robot + " -o " +
                     shell_quoted(plan_) + extra);
  }

  fs::path dir_;
  fs::path parts_;
  fs::path plan_;
  fs::path program_;
};

TEST_F(Refusals, FarPartPointIsUnreachableNamedByFileLineAndPoint) {
  // 1e308 mm overflows the squares of the IK, which once gave NaN joints; 1e200 m as well: out
  // of any file's range, refused as read. 100 m is in range and out of reach.
  for (const char* far : {"1e308,0,0", "1e200,1e200,0", "-1.7e308,1.7e308,1e308", "1e5,0,0"}) {
    write_text(parts_, "point,robot_x_mm,robot_y_mm,robot_z_mm\nnear,480,220,300\nA," +
                           std::string(far) + "\n");
    const bool in_range = std::string(far) == "1e5,0,0";
    for (const char* robot : {"ur5", "lwr4"}) {
      const CliResult r = plan(robot, " --export csv --program " + shell_quoted(program_));
      expect_refused(r, parts_.string() + ":3: ",
                     in_range ? "A (unreachable: the wrist centre is " : "is out of range");
      if (in_range) {
        EXPECT_NE(r.err.find("from the shoulder"), std::string::npos) << r.err;
      }
      EXPECT_EQ(r.err.find("inf "), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(plan_));
      EXPECT_FALSE(fs::exists(program_));
    }
  }
  // The same for a point 10 m away, and with home joints (the nearest-solution path).
  write_text(parts_, "point,robot_x_mm,robot_y_mm,robot_z_mm\nA,1e5,0,0\n");
  expect_refused(plan("ur5", " --home-deg 0 -90 0 -90 0 0"),
                 parts_.string() + ":2: ", "A (unreachable");
  write_text(parts_, "point,robot_x_mm,robot_y_mm,robot_z_mm\nA,10000,0,0\n");
  expect_refused(plan("ur5"), parts_.string() + ":2: ", "beyond the arm's reach");
}

TEST_F(Refusals, PartLabelAPlanCannotHoldIsRefusedByTheReader) {
  for (const char* label : {"P\"q);popup(\"x", "Pq\"", "#P"}) {
    // '#P' as the first field would be a comment: give it in the second column.
    write_text(parts_,
               "robot_x_mm,point,robot_y_mm,robot_z_mm\n450," + std::string(label) + ",-100,250\n");
    const CliResult r =
        run_vrreg("plan --parts " + shell_quoted(parts_) +
                  " --halfwidth-mm 10 --spacing-mm 20 --robot ur5 --export urscript --program " +
                  shell_quoted(program_) + " -o " + shell_quoted(plan_));
    expect_refused(r, parts_.string() + ":2: ", "has a quote or a leading '#'");
    EXPECT_FALSE(fs::exists(program_)) << label;
    EXPECT_FALSE(fs::exists(plan_)) << label;
  }
}

TEST_F(Refusals, ACommandWritesAllItsOutputsOrNone) {
  write_text(parts_, "point,robot_x_mm,robot_y_mm,robot_z_mm\nA,450,-100,250\n");
  const fs::path missing_dir_plan = dir_ / "no-such-dir" / "plan.csv";
  const std::string plan_args = "plan --parts " + shell_quoted(parts_) +
                                " --halfwidth-mm 10 --spacing-mm 20 --robot ur5 --export "
                                "urscript --program " +
                                shell_quoted(program_);
  // -o cannot be written after --program was made: neither is written.
  CliResult r = run_vrreg(plan_args + " -o " + shell_quoted(missing_dir_plan));
  expect_refused(r, missing_dir_plan.string(), "cannot create a temporary file");
  EXPECT_FALSE(fs::exists(program_));
  // An earlier program stays as it was.
  write_text(program_, "previous program\n");
  r = run_vrreg(plan_args + " -o " + shell_quoted(missing_dir_plan));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(read_text(program_), "previous program\n");
  // Both written when both can be.
  r = run_vrreg(plan_args + " -o " + shell_quoted(plan_));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(read_text(program_).find("movej("), std::string::npos);
  EXPECT_NE(read_text(plan_).find("\nA,target,A,"), std::string::npos);
  for (const fs::directory_entry& e : fs::directory_iterator(dir_)) {
    EXPECT_FALSE(e.path().filename().string().starts_with(".vrreg-")) << e.path();
  }

  // simulate: --write-errors is not written when -o cannot be.
  const fs::path errors = dir_ / "errors.json";
  r = run_vrreg("simulate ur5 A1 --write-errors " + shell_quoted(errors) + " -o " +
                shell_quoted(dir_ / "no-such-dir" / "a1.csv"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_FALSE(fs::exists(errors));
  EXPECT_TRUE(r.out.empty()) << r.out;
  // ... nor when the simulation itself fails.
  r = run_vrreg("simulate ur5 C --write-errors " + shell_quoted(errors) + " -o " +
                shell_quoted(dir_ / "c.csv"));
  EXPECT_NE(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(errors));
}

TEST_F(Refusals, ReproduceJsonOfTheWrongShapeNamesTheFileAndKey) {
  const fs::path rep = dir_ / "rep";
  fs::create_directories(rep);
  write_text(rep / "reproduce.json",
             R"({"format": "vrreg-reproduce", "version": 1, "seeds": "1, 2"})");
  const fs::path html = dir_ / "r.html";
  const CliResult r =
      run_vrreg("report --reproduce " + shell_quoted(rep) + " -o " + shell_quoted(html));
  expect_refused(r, (rep / "reproduce.json").string() + ": ",
                 "reproduce.seeds: expected an array of numbers");
  EXPECT_FALSE(fs::exists(html));
}

TEST_F(Refusals, SeedsAtTheTopOfTheRangeEndOrAreRefused) {
  // `timeout` ends the command should the seed loop wrap again (exit 124).
  CliResult r = run_vrreg_in(dir_, "calibrate-testbeds --seeds 18446744073709551615 --only ur5",
                             "timeout 120");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\n| 18446744073709551615 |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 seeds in"), std::string::npos) << r.out;
  r = run_vrreg_in(dir_,
                   "calibrate-testbeds --seeds 18446744073709551614-18446744073709551615 --only "
                   "ur5",
                   "timeout 120");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2 seeds in"), std::string::npos) << r.out;
  for (const char* args : {"reproduce --seed 18446744073709551615 --seeds 2 --out ''",
                           "robust-study --seed 18446744073709551614 --seeds 3"}) {
    r = run_vrreg_in(dir_, args, "timeout 120");
    expect_refused(r, "18446744073709551615", "pass 2^64 - 1");
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

// A joint-space model of simulated UR5 data (joints in the file), made once for the suite.
class JointModel : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fresh_dir("JointModel"));
    const CliResult sim = run_vrreg("simulate ur5 A1 --seed 1 -o " + shell_quoted(data()));
    ASSERT_EQ(sim.status, 0) << sim.err;
    const CliResult reg =
        run_vrreg("register --fiducials " + shell_quoted(data()) +
                  " --interpolation joint --robot ur5 -o " + shell_quoted(model()));
    ASSERT_EQ(reg.status, 0) << reg.err;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path data() { return *dir_ / "a1.csv"; }
  static fs::path model() { return *dir_ / "joint.json"; }

  // The model with `edit` applied, written to `name`; evaluate on it must name it and `key`.
  static void expect_damaged_model_named(const std::string& name, const std::string& key,
                                         const std::function<void(nlohmann::json&)>& edit) {
    for (const bool with_corrector : {true, false}) {
      nlohmann::json doc = nlohmann::json::parse(read_text(model()));
      if (!with_corrector) doc.erase("corrector");
      edit(doc);
      const fs::path damaged = *dir_ / name;
      write_text(damaged, doc.dump(1));
      for (const std::string& command :
           {"evaluate --model " + shell_quoted(damaged) + " --targets " + shell_quoted(data()),
            "correct --model " + shell_quoted(damaged) + " --points " + shell_quoted(data()) +
                " -o " + shell_quoted(*dir_ / "out.csv")}) {
        const CliResult r = run_vrreg(command);
        expect_refused(r, damaged.string() + ": '" + key + "': ", "joint");
        EXPECT_EQ(r.err.find(data().string()), std::string::npos) << r.err;
      }
      EXPECT_FALSE(fs::exists(*dir_ / "out.csv"));
    }
  }

  static fs::path* dir_;
};

fs::path* JointModel::dir_ = nullptr;

TEST_F(JointModel, IntactModelEvaluates) {
  const CliResult r =
      run_vrreg("evaluate --model " + shell_quoted(model()) + " --targets " + shell_quoted(data()));
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(JointModel, FiducialJointsShortOrMissingNameTheModelFileAndKey) {
  expect_damaged_model_named("short.json", "fiducials[0].q_rad", [](nlohmann::json& doc) {
    doc["fiducials"][0]["q_rad"].erase(doc["fiducials"][0]["q_rad"].size() - 1);
  });
  expect_damaged_model_named("missing.json", "fiducials[0].q_rad",
                             [](nlohmann::json& doc) { doc["fiducials"][0].erase("q_rad"); });
  expect_damaged_model_named("none.json", "fiducials[0].q_rad", [](nlohmann::json& doc) {
    for (nlohmann::json& f : doc["fiducials"]) f.erase("q_rad");
  });
  expect_damaged_model_named("third.json", "fiducials[2].q_rad", [](nlohmann::json& doc) {
    doc["fiducials"][2]["q_rad"].push_back(0.5);
  });
}

TEST_F(JointModel, DeletedRobotNamesTheModelFile) {
  expect_damaged_model_named("no-robot.json", "robot",
                             [](nlohmann::json& doc) { doc.erase("robot"); });
}

TEST_F(JointModel, RegisterRefusesJointInterpolationWithoutJointsOrWithAnotherRobot) {
  const fs::path out = *dir_ / "refused.json";
  // The example cell has no joint columns.
  CliResult r = run_vrreg("register --fiducials " + shell_quoted(kExampleCell) +
                          " --interpolation joint --robot ur5 -o " + shell_quoted(out));
  expect_refused(r, kExampleCell + ": ", "the fiducials have no joint angles");
  // UR5 data (6 joints) with a 7-joint robot.
  r = run_vrreg("register --fiducials " + shell_quoted(data()) +
                " --interpolation joint --robot lwr4 -o " + shell_quoted(out));
  expect_refused(r, data().string() + ": ", "the fiducials have 6 joint angles, the robot 7");
  // And without a robot at all.
  r = run_vrreg("register --fiducials " + shell_quoted(data()) + " --interpolation joint -o " +
                shell_quoted(out));
  expect_refused(r, data().string() + ": ", "no robot given (--robot)");
  EXPECT_FALSE(fs::exists(out));
}

TEST(EmptyInputName, IsAUsageErrorNamingTheOption) {
  const std::string cell = shell_quoted(kExampleCell);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"register --fiducials ''", "--fiducials: needs a file name"},
      {"evaluate --model '' --targets " + cell, "--model: needs a file name"},
      {"evaluate --model m.json --targets ''", "--targets: needs a file name"},
      {"correct --model m.json --points '' -o out.csv", "--points: needs a file name"},
      {"export --model '' --format json", "--model: needs a file name"},
      {"plan --parts '' --halfwidth-mm 10 --spacing-mm 20 --robot ur5",
       "--parts: needs a file name"},
      {"plan --parts " + cell + " --halfwidth-mm 10 --spacing-mm 20 --robot ''",
       "--robot: needs a robot name or file"},
      {"register --fiducials " + cell + " --interpolation joint --robot ''",
       "--robot: needs a robot name or file"},
      {"simulate ur5 --plan '' -o out.csv", "--plan: needs a file name"},
      {"simulate ur5 A1 --errors '' -o out.csv", "--errors: needs a file name"},
      {"report --reproduce '' -o r.html", "--reproduce: needs a directory name"},
      {"calibrate-testbeds --ur5-errors ''", "--ur5-errors: needs a file name"},
      {"fk '' 0 0 0 0 0 0", "robot: needs a robot name or file"},
  };
  const fs::path dir = fresh_dir("EmptyInputName");
  for (const auto& [args, words] : cases) {
    const CliResult r = run_vrreg_in(dir, args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_EQ(lines_of(r.err), 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find(": : "), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
