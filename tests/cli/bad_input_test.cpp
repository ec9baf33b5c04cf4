// SPDX-License-Identifier: Apache-2.0
// Every bad input: non-zero exit, one line on stderr naming the file (and line), no crash, no
// hang, no output file left behind.
#include <unistd.h>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

const char* kHeader = "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n";

std::string good_rows() {
  return "F1,fiducial,0,0,0,10,20,30\n"
         "F2,fiducial,100,0,0,110,20,30\n"
         "F3,fiducial,0,100,0,10,120,30\n"
         "F4,fiducial,0,0,100,10,20,130\n"
         "T1,target,50,50,50,60,70,80\n";
}

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    model_ = dir_ / "model.json";
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs register on `content`; expects failure naming the file (and `line` when > 0).
  void expect_register_fails(const std::string& content, int line, const std::string& words = "") {
    const fs::path csv = dir_ / "in.csv";
    write_text(csv, content);
    const CliResult r = run_vrreg("register --fiducials '" + csv.string() + "' -o '" +
                                  model_.string() + "'");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(csv.string()), std::string::npos) << r.err;
    if (line > 0) {
      EXPECT_NE(r.err.find(csv.string() + ":" + std::to_string(line) + ":"), std::string::npos)
          << r.err;
    }
    if (!words.empty()) {
      EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    }
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(model_));
  }

  fs::path dir_;
  fs::path model_;
};

TEST_F(BadInput, EmptyFile) { expect_register_fails("", 0); }
TEST_F(BadInput, HeaderOnly) { expect_register_fails(kHeader, 0); }
TEST_F(BadInput, MissingColumn) {
  expect_register_fails("point,role,robot_x_mm,robot_y_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n", 1,
                        "robot_z");
}
TEST_F(BadInput, UnknownUnitSuffix) {
  expect_register_fails(
      "point,role,robot_x_in,robot_y_in,robot_z_in,sensor_x_in,sensor_y_in,sensor_z_in\n" +
          good_rows(),
      1);
}
TEST_F(BadInput, MixedUnitSuffixes) {
  expect_register_fails(
      "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_m,sensor_y_m,sensor_z_m\n" +
          good_rows(),
      1);
}
TEST_F(BadInput, NaNValue) {
  expect_register_fails(std::string(kHeader) + good_rows() + "F5,fiducial,1,2,nan,4,5,6\n", 7);
}
TEST_F(BadInput, InfValue) {
  expect_register_fails(std::string(kHeader) + "F0,fiducial,inf,2,3,4,5,6\n" + good_rows(), 2);
}
TEST_F(BadInput, NonNumericValue) {
  expect_register_fails(std::string(kHeader) + good_rows() + "F5,fiducial,1,2,3,4,5,six\n", 7);
}
TEST_F(BadInput, ShortRow) {
  expect_register_fails(std::string(kHeader) + "F0,fiducial,1,2,3,4,5\n" + good_rows(), 2);
}
TEST_F(BadInput, UnknownRole) {
  expect_register_fails(std::string(kHeader) + good_rows() + "F5,anchor,1,2,3,4,5,6\n", 7, "anchor");
}
TEST_F(BadInput, ConflictingCoordinatesForOnePoint) {
  expect_register_fails(std::string(kHeader) + good_rows() + "F1,fiducial,0,0,1,10,20,30\n", 7);
}
TEST_F(BadInput, FewerThanThreeFiducials) {
  expect_register_fails(std::string(kHeader) + "F1,fiducial,0,0,0,1,2,3\nF2,fiducial,1,0,0,2,2,3\n",
                        0, "at least 3");
}
TEST_F(BadInput, CollinearFiducials) {
  expect_register_fails(std::string(kHeader) +
                            "F1,fiducial,0,0,0,1,2,3\nF2,fiducial,10,0,0,11,2,3\n"
                            "F3,fiducial,20,0,0,21,2,3\nF4,fiducial,30,0,0,31,2,3\n",
                        0, "collinear");
}
TEST_F(BadInput, CoincidentFiducials) {
  expect_register_fails(std::string(kHeader) +
                            "F1,fiducial,0,0,0,1,2,3\nF2,fiducial,0,0,0,1,2,3\n"
                            "F3,fiducial,0,0,0,1,2,3\n",
                        0, "coincide");
}
TEST_F(BadInput, BinaryGarbage) {
  std::string garbage(4096, '\0');
  for (std::size_t k = 0; k < garbage.size(); ++k) garbage[k] = static_cast<char>((k * 131) % 256);
  expect_register_fails(garbage, 0);
}
TEST_F(BadInput, TwoMegabyteLine) {
  expect_register_fails(std::string(kHeader) + "F1,fiducial," + std::string(2 << 20, '1') + "\n", 2);
}
TEST_F(BadInput, MissingFile) {
  const CliResult r = run_vrreg("register --fiducials '" + (dir_ / "nope.csv").string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("nope.csv"), std::string::npos) << r.err;
}

TEST_F(BadInput, NoTargets) {
  const fs::path csv = dir_ / "fid.csv";
  write_text(csv, std::string(kHeader) + "F1,fiducial,0,0,0,10,20,30\nF2,fiducial,100,0,0,110,20,30\n"
                                         "F3,fiducial,0,100,0,10,120,30\nF4,fiducial,0,0,100,10,20,130\n");
  ASSERT_EQ(run_vrreg("register --fiducials '" + csv.string() + "' -o '" + model_.string() + "'").status, 0);
  const fs::path per_target = dir_ / "pt.csv";
  const CliResult r = run_vrreg("evaluate --model '" + model_.string() + "' --targets '" +
                                csv.string() + "' --per-target '" + per_target.string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("no target rows"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(per_target));
}

TEST_F(BadInput, BrokenModelFiles) {
  const fs::path csv = dir_ / "cell.csv";
  write_text(csv, std::string(kHeader) + good_rows());
  ASSERT_EQ(run_vrreg("register --fiducials '" + csv.string() + "' -o '" + model_.string() + "'").status, 0);
  const std::string text = read_text(model_);
  const std::vector<std::pair<std::string, std::string>> broken = {
      {"truncated", text.substr(0, text.size() / 2)},
      {"empty", ""},
      {"garbage", "\x01\x02 not json"},
      {"version", [&] {
         std::string t = text;
         const auto at = t.find("\"version\": 1");
         return at == std::string::npos ? std::string("{}") : t.replace(at, 12, "\"version\": 7");
       }()},
  };
  for (const auto& [name, content] : broken) {
    const fs::path bad = dir_ / (name + ".json");
    write_text(bad, content);
    const fs::path out = dir_ / "out.csv";
    const CliResult r = run_vrreg("correct --model '" + bad.string() + "' --points '" +
                                  csv.string() + "' -o '" + out.string() + "'");
    EXPECT_EQ(r.status, 1) << name;
    EXPECT_NE(r.err.find(bad.string()), std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << name;
  }
}

TEST_F(BadInput, AcceptedVariants) {
  // CRLF, a UTF-8 BOM, comment lines, no final newline, _m units.
  std::string text = "\xEF\xBB\xBF# a comment\r\n"
                     "point,role,robot_x_m,robot_y_m,robot_z_m,sensor_x_m,sensor_y_m,sensor_z_m\r\n"
                     "# another\r\n"
                     "F1,fiducial,0,0,0,0.01,0.02,0.03\r\n"
                     "F2,fiducial,0.1,0,0,0.11,0.02,0.03\r\n"
                     "F3,fiducial,0,0.1,0,0.01,0.12,0.03\r\n"
                     "F4,fiducial,0,0,0.1,0.01,0.02,0.13";
  const fs::path csv = dir_ / "variants.csv";
  write_text(csv, text);
  const CliResult r = run_vrreg("register --fiducials '" + csv.string() + "' --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"n_fiducials\": 4"), std::string::npos) << r.out;
}

TEST(Cli, HelpEverywhere) {
  for (const char* cmd : {"", "register ", "evaluate ", "correct "}) {
    const CliResult r = run_vrreg(std::string(cmd) + "--help");
    EXPECT_EQ(r.status, 0) << cmd;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << cmd;
  }
  EXPECT_EQ(run_vrreg("register").status, 2);  // missing --fiducials: a usage error
  EXPECT_EQ(run_vrreg("no-such-command").status, 2);
}

}  // namespace
}  // namespace vrreg::testing
