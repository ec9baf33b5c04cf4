// SPDX-License-Identifier: Apache-2.0
// vrreg simulate as a user runs it: same seed same bytes, the seed printed, error-model files,
// one-line errors, and the paper's register -> evaluate flow on a simulated A1.
#include <gtest/gtest.h>
#include <unistd.h>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

class SimulateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return "'" + (dir_ / name).string() + "'"; }
  fs::path dir_;
};

TEST_F(SimulateCli, SameSeedSameBytesAndTheSeedIsPrinted) {
  const CliResult a = run_vrreg("simulate ur5 A1 --seed 5 -o " + path("a.csv"));
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_NE(a.out.find("seed 5"), std::string::npos) << a.out;
  EXPECT_NE(a.out.find("1287 locations (1167 fiducials, 120 targets)"), std::string::npos) << a.out;
  ASSERT_EQ(run_vrreg("simulate ur5 a1 --seed 5 -o " + path("b.csv")).status, 0);
  ASSERT_EQ(run_vrreg("simulate ur5 A1 --seed 6 -o " + path("c.csv")).status, 0);
  EXPECT_TRUE(read_text(dir_ / "a.csv") == read_text(dir_ / "b.csv"));
  EXPECT_FALSE(read_text(dir_ / "a.csv") == read_text(dir_ / "c.csv"));
  const CliResult d = run_vrreg("simulate ur5 A1 -o " + path("d.csv"));
  EXPECT_NE(d.out.find("seed 1"), std::string::npos) << d.out;
}

TEST_F(SimulateCli, ErrorModelFileOverridesTheDefaults) {
  ASSERT_EQ(run_vrreg("simulate lwr4 --write-errors " + path("e.json")).status, 0);
  std::string text = read_text(dir_ / "e.json");
  const std::string key = "\"repeatability_sigma_mm\": 0.03";
  ASSERT_NE(text.find(key), std::string::npos) << text;
  text.replace(text.find(key), key.size(), "\"repeatability_sigma_mm\": 0.07");
  write_text(dir_ / "e.json", text);
  const CliResult r =
      run_vrreg("simulate lwr4 grid --errors " + path("e.json") + " -o " + path("g.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(read_text(dir_ / "g.csv").find("repeatability sigma 0.07 mm"), std::string::npos);
}

TEST_F(SimulateCli, BadInputFailsWithOneLine) {
  for (const std::string& args :
       {std::string("simulate ur10 A1 -o ") + path("x.csv"),
        "simulate ur5 grid -o " + path("x.csv"), "simulate lwr4 A1 -o " + path("x.csv"),
        std::string("simulate ur5 A1"),
        "simulate ur5 A1 --errors " + path("missing.json") + " -o " + path("x.csv")}) {
    const CliResult r = run_vrreg(args);
    EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.csv")) << args;
  }
}

TEST_F(SimulateCli, RegisterAndEvaluateLikeThePapersTable1) {
  ASSERT_EQ(run_vrreg("simulate ur5 A1 -o " + path("a1.csv")).status, 0);
  const CliResult reg = run_vrreg("register --fiducials " + path("a1.csv") + " -o " +
                                  path("m.json") + " --sigma-rep-mm 0.1");
  ASSERT_EQ(reg.status, 0) << reg.err;
  EXPECT_NE(reg.out.find("registered 1167 fiducials"), std::string::npos) << reg.out;
  const CliResult ev = run_vrreg("evaluate --model " + path("m.json") + " --targets " +
                                 path("a1.csv") + " --interpolation octuplet --cube-mm 50 --json");
  ASSERT_EQ(ev.status, 0) << ev.err;
  EXPECT_NE(ev.out.find("\"n_targets\": 120"), std::string::npos) << ev.out;
  EXPECT_NE(ev.out.find("\"cor_rms_t_mm\""), std::string::npos) << ev.out;
}

}  // namespace
}  // namespace vrreg::testing
