// SPDX-License-Identifier: Apache-2.0
// Usage errors are one line with exit status 2; an output that is a directory, FIFO or device is
// refused before any work (before the inputs are even read); above 20 000 fiducials `register`
// samples sigma_L and says so.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

long newline_count(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(UsageErrors, AreOneLineWithStatus2) {
  const fs::path dir = fresh_dir("usage");
  for (const std::string& args : std::vector<std::string>{
           "simulate ur5 A1 --seed -1 -o " + shell_quoted(dir / "s.csv"), "simulate ur5 A1 -o ''",
           "register", "register --fiducials x.csv --no-such-flag", "no-such-command",
           "no-such-service --help", "--version no-such-service",
           "evaluate --model m.json --targets t.csv --per-target ''"}) {
    const CliResult r = run_vrreg(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(newline_count(r.err), 1) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("vrreg: usage error: ", 0), 0U) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("--help"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
  }
  EXPECT_NE(run_vrreg("simulate ur5 A1 --seed -1 -o x.csv").err.find("vrreg simulate --help"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "s.csv"));
  EXPECT_EQ(run_vrreg("--help").status, 0);
  EXPECT_EQ(run_vrreg("register --help").status, 0);
  fs::remove_all(dir);
}

TEST(OutputsThatAreNotFiles, AreRefusedBeforeTheInputsAreRead) {
  const fs::path dir = fresh_dir("not-files");
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  fs::create_directory(dir / "d");
  const std::string missing =
      shell_quoted(dir / "missing.csv");  // reading it would fail differently
  for (const fs::path& out : {fifo, dir / "d"}) {
    for (const std::string& args :
         {"register --fiducials " + missing + " -o " + shell_quoted(out),
          "evaluate --model " + missing + " --targets " + missing + " --per-target " +
              shell_quoted(out),
          "correct --model " + missing + " --points " + missing + " -o " + shell_quoted(out),
          "simulate ur5 A1 -o " + shell_quoted(out),
          "simulate ur5 --write-errors " + shell_quoted(out)}) {
      const CliResult r = run_vrreg(args);
      EXPECT_EQ(r.status, 1) << args;
      EXPECT_EQ(newline_count(r.err), 1) << args << "\n" << r.err;
      EXPECT_NE(r.err.find(out.string() + ": is a"), std::string::npos) << args << "\n" << r.err;
      EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
    }
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_directory(dir / "d"));
  fs::remove_all(dir);
}

// J fiducials on a 2 mm grid, the sensor frame turned and shifted, a smooth robot error.
void write_fiducials(const fs::path& path, int j) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fprintf(f,
               "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n");
  for (int k = 0; k < j; ++k) {
    const double x = 300 + 2.0 * (k % 30), y = -200 + 2.0 * ((k / 30) % 30),
                 z = 100 + 2.0 * (k / 900);
    const double ex = 0.2 * std::sin(0.05 * y), ez = 0.1 * std::cos(0.07 * x);
    std::fprintf(f, "F%d,fiducial,%g,%g,%g,%.6f,%.6f,%.6f\n", k, x, y, z, y + ex - 50, -x + 600,
                 z + ez + 2000);
  }
  std::fclose(f);
}

TEST(LargeRegistration, SamplesSigmaLAboveTwentyThousandFiducialsAndSaysSo) {
  const fs::path dir = fresh_dir("large");
  write_fiducials(dir / "f.csv", 20001);
  const CliResult run = run_vrreg("register --fiducials " + shell_quoted(dir / "f.csv") +
                                  " --json -o " + shell_quoted(dir / "m.json"));
  ASSERT_EQ(run.status, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_TRUE(j.contains("sigma_l_sampling")) << run.out;
  EXPECT_EQ(j["sigma_l_sampling"]["pairs"], 10000000);
  EXPECT_EQ(j["sigma_l_sampling"]["pairs_total"], 20001LL * 20000 / 2);
  EXPECT_EQ(j["pairs"], 10000000);
  const double low = j["sigma_l_sampling"]["interval_mm"][0];
  const double high = j["sigma_l_sampling"]["interval_mm"][1];
  EXPECT_LT(low, j["sigma_l_mm"].get<double>());
  EXPECT_GT(high, j["sigma_l_mm"].get<double>());
  const auto model = nlohmann::json::parse(read_text(dir / "m.json"));
  EXPECT_EQ(model["sigma_l_sampling"]["pairs"], 10000000);
  EXPECT_EQ(model["sigma_l_m"].get<double>() * 1e3, j["sigma_l_mm"].get<double>());

  const CliResult text = run_vrreg("register --fiducials " + shell_quoted(dir / "f.csv"));
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("SAMPLED: 10000000 of 200010000 pairs"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("--exact-sigma-l"), std::string::npos) << text.out;
  // Same seed, same bytes.
  EXPECT_EQ(run_vrreg("register --fiducials " + shell_quoted(dir / "f.csv")).out, text.out);

  // At 20 000 fiducials every pair is used, and the model has no sampling key.
  write_fiducials(dir / "g.csv", 20000);
  const CliResult exact =
      run_vrreg("register --fiducials " + shell_quoted(dir / "g.csv") + " --json");
  ASSERT_EQ(exact.status, 0) << exact.err;
  const auto e = nlohmann::json::parse(exact.out);
  EXPECT_FALSE(e.contains("sigma_l_sampling"));
  EXPECT_EQ(e["pairs"], 20000LL * 19999 / 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
