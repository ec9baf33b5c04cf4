// SPDX-License-Identifier: Apache-2.0
// No command writes over its own input, however the output is spelled: the same path, through
// `sub/..`, a symbolic link or a hard link to the input. Each refusal exits 1 with one line naming
// both files, and the input is byte for byte what it was.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "robot_files.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

const char* kOverwriteParts =
    "point,robot_x_mm,robot_y_mm,robot_z_mm\n"
    "hole_A,420,-140,250\nhole_B,480,-140,250\npin_C,480,-60,260\npin_D,420,-60,240\n";

// Real inputs for every command, made once by the commands themselves.
class InputOverwrite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fresh_dir("input-overwrite"));
    const fs::path& d = *dir_;
    write_text(d / "parts.csv", kOverwriteParts);
    write_text(d / "robot.yaml", kUr5RobotYaml);
    write_text(d / "token.txt", "s3cret-token\n");
    fs::create_directories(d / "rep");
    for (const std::string& args :
         {"simulate ur5 A1 -o " + shell_quoted(d / "meas.csv") + " --write-errors " +
              shell_quoted(d / "errors.json"),
          "register --fiducials " + shell_quoted(d / "meas.csv") + " -o " +
              shell_quoted(d / "model.json"),
          "plan --parts " + shell_quoted(d / "parts.csv") +
              " --halfwidth-mm 10 --spacing-mm 5 --robot ur5 -o " + shell_quoted(d / "plan.csv"),
          "reproduce --seeds 1 --only lwr4 --no-report --quiet --out " + shell_quoted(d / "rep")}) {
      const CliResult r = run_vrreg(args);
      ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
    }
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static fs::path in(const std::string& name) { return *dir_ / name; }

  // `args` with {IN} (a fresh copy of `input` in its own directory) and {OUT} (every spelling of
  // that copy): refused each time, the input unchanged.
  void expect_refused(const std::string& args, const fs::path& input, const std::string& option) {
    expect_refused_in(args, input, option, "");
  }
  void expect_refused_with_timeout(const std::string& args, const fs::path& input,
                                   const std::string& option) {
    expect_refused_in(args, input, option, "timeout 60");
  }
  void expect_refused_in(const std::string& args, const fs::path& input, const std::string& option,
                         const std::string& prefix) {
    const fs::path work =
        fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(work / "sub");
    const fs::path copy = work / input.filename();
    fs::copy_file(input, copy);
    const std::string bytes = read_text(copy);
    fs::create_symlink(copy, work / "link");
    fs::create_hard_link(copy, work / "hard");
    const std::vector<fs::path> spellings = {copy, work / "sub" / ".." / input.filename(),
                                             work / "link", work / "hard"};
    for (const fs::path& out : spellings) {
      std::string line = args;
      line.replace(line.find("{IN}"), 4, shell_quoted(copy));
      line.replace(line.find("{OUT}"), 5, shell_quoted(out));
      const CliResult r = run_vrreg_in({}, line, prefix);
      EXPECT_EQ(r.status, 1) << line << "\n" << r.out << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_NE(r.err.find(out.string() + ": "), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(option + " '" + copy.string() + "'"), std::string::npos) << r.err;
      EXPECT_EQ(read_text(copy), bytes) << line;
      EXPECT_TRUE(fs::is_symlink(work / "link"));
      EXPECT_TRUE(fs::is_regular_file(work / "hard"));
    }
    fs::remove_all(work);
  }

  static fs::path* dir_;
};

fs::path* InputOverwrite::dir_ = nullptr;

TEST_F(InputOverwrite, Register) {
  expect_refused("register --fiducials {IN} -o {OUT}", in("meas.csv"), "--fiducials");
}

TEST_F(InputOverwrite, Evaluate) {
  expect_refused(
      "evaluate --model " + shell_quoted(in("model.json")) + " --targets {IN} --per-target {OUT}",
      in("meas.csv"), "--targets");
  expect_refused(
      "evaluate --model {IN} --targets " + shell_quoted(in("meas.csv")) + " --per-target {OUT}",
      in("model.json"), "--model");
}

TEST_F(InputOverwrite, Correct) {
  expect_refused("correct --model " + shell_quoted(in("model.json")) + " --points {IN} -o {OUT}",
                 in("meas.csv"), "--points");
  expect_refused("correct --model {IN} --points " + shell_quoted(in("meas.csv")) + " -o {OUT}",
                 in("model.json"), "--model");
}

TEST_F(InputOverwrite, Simulate) {
  expect_refused("simulate ur5 --plan {IN} -o {OUT}", in("plan.csv"), "--plan");
  expect_refused("simulate ur5 A1 --errors {IN} -o {OUT}", in("errors.json"), "--errors");
  expect_refused("simulate ur5 A1 --errors {IN} -o " + shell_quoted(in("unused.csv")) +
                     " --write-errors {OUT}",
                 in("errors.json"), "--errors");
}

TEST_F(InputOverwrite, Report) {
  const std::string cell = "report --model " + shell_quoted(in("model.json")) + " --targets " +
                           shell_quoted(in("meas.csv"));
  expect_refused("report --model {IN} --targets " + shell_quoted(in("meas.csv")) + " -o {OUT}",
                 in("model.json"), "--model");
  expect_refused("report --model " + shell_quoted(in("model.json")) + " --targets {IN} -o {OUT}",
                 in("meas.csv"), "--targets");
  expect_refused(cell + " --plan {IN} -o {OUT}", in("plan.csv"), "--plan");
}

TEST_F(InputOverwrite, ReportOfAReproduceDirectory) {
  // The input is DIR/reproduce.json: copy the directory so each spelling has its own.
  const fs::path work = fresh_dir("report-reproduce");
  fs::copy(in("rep"), work / "rep");
  const fs::path input = work / "rep" / "reproduce.json";
  const std::string bytes = read_text(input);
  for (const fs::path& out : {input, work / "rep" / ".." / "rep" / "reproduce.json"}) {
    const CliResult r =
        run_vrreg("report --reproduce " + shell_quoted(work / "rep") + " -o " + shell_quoted(out));
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--reproduce '" + input.string() + "'"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(input), bytes);
  }
  fs::remove_all(work);
}

TEST_F(InputOverwrite, Plan) {
  const std::string grid = " --halfwidth-mm 10 --spacing-mm 5";
  expect_refused("plan --parts {IN}" + grid + " --robot ur5 -o {OUT}", in("parts.csv"), "--parts");
  expect_refused("plan --parts " + shell_quoted(in("parts.csv")) + grid + " --robot {IN} -o {OUT}",
                 in("robot.yaml"), "--robot");
}

TEST_F(InputOverwrite, Calibrate) {
  expect_refused("calibrate-testbeds --only ur5 --seeds 1 --ur5-errors {IN} -o {OUT}",
                 in("errors.json"), "--ur5-errors");
}

TEST_F(InputOverwrite, RobotFiles) {
  const std::string meas = shell_quoted(in("meas.csv"));
  const std::string model = shell_quoted(in("model.json"));
  expect_refused("register --fiducials " + meas + " --robot {IN} -o {OUT}", in("robot.yaml"),
                 "--robot");
  expect_refused(
      "evaluate --model " + model + " --targets " + meas + " --robot {IN} --per-target {OUT}",
      in("robot.yaml"), "--robot");
  expect_refused("correct --model " + model + " --points " + meas + " --robot {IN} -o {OUT}",
                 in("robot.yaml"), "--robot");
}

TEST_F(InputOverwrite, Snippet) {
  expect_refused("snippet urscript --model cell --token-file {IN} -o {OUT}", in("token.txt"),
                 "--token-file");
  expect_refused("snippet krl --model cell --token-file {IN} -o " +
                     shell_quoted(in("VRREG_CORRECT.src")) + " --eki-config {OUT}",
                 in("token.txt"), "--token-file");
  EXPECT_FALSE(fs::exists(in("VRREG_CORRECT.src")));
}

TEST_F(InputOverwrite, SnippetProgramAndConfigurationMayNotBeOneFile) {
  const fs::path work = fresh_dir("snippet-two-outputs");
  fs::create_directories(work / "sub");
  const CliResult r = run_vrreg("snippet krl --model cell -o " + shell_quoted(work / "x.src") +
                                " --eki-config " + shell_quoted(work / "sub" / ".." / "x.src"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("--eki-config is the same file as -o"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(work / "x.src"));
  fs::remove_all(work);
}

// The service refuses before it loads a model or opens a port; `timeout` stops a service that
// would start instead.
TEST_F(InputOverwrite, ServeAuditLog) {
  const std::string serve = "serve --listen 127.0.0.1:0 --reload-poll-ms 0";
  std::string line = serve + " --model cell={IN} --audit-log {OUT}";
  expect_refused_with_timeout(line, in("model.json"), "--model");
  line = serve + " --model {IN} --audit-log {OUT}";
  expect_refused_with_timeout(line, in("model.json"), "--model");
  line =
      serve + " --model " + shell_quoted(in("model.json")) + " --token-file {IN} --audit-log {OUT}";
  expect_refused_with_timeout(line, in("token.txt"), "--token-file");
}

TEST_F(InputOverwrite, ServeAuditLogRotationMayNotReachAnInput) {
  // Rotation renames LOG to LOG.1: a model named so would be replaced.
  const fs::path work = fresh_dir("serve-rotation");
  fs::copy_file(in("model.json"), work / "audit.log.1");
  const std::string bytes = read_text(work / "audit.log.1");
  const CliResult r =
      run_vrreg_in({},
                   "serve --listen 127.0.0.1:0 --model cell=" + shell_quoted(work / "audit.log.1") +
                       " --audit-log " + shell_quoted(work / "audit.log"),
                   "timeout 60");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("--audit-log is the input --model"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(work / "audit.log.1"), bytes);
  EXPECT_FALSE(fs::exists(work / "audit.log"));
  fs::remove_all(work);
}

TEST_F(InputOverwrite, TwoOutputsOfOneCommandMayNotBeOneFile) {
  const fs::path work = fresh_dir("two-outputs");
  fs::create_directories(work / "sub");
  const CliResult r = run_vrreg("simulate ur5 A1 -o " + shell_quoted(work / "x") +
                                " --write-errors " + shell_quoted(work / "sub" / ".." / "x"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("is the same file as -o"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(work / "x"));
  fs::remove_all(work);
}

}  // namespace
}  // namespace vrreg::testing
