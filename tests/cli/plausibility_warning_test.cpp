// SPDX-License-Identifier: Apache-2.0
// Millimetres written in `_m` columns make a 100 mm cell 100 m wide: the command says so on stderr
// (and goes on: the numbers are consistent, only their unit is suspect); a cell in metres or in
// millimetres with `_mm` columns gets no warning.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <utility>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

// 27 fiducials on a 50-unit grid and 8 targets at the cube centres, in `unit` columns; the sensor
// sees the robot shifted and with a small smooth error, in the same numbers.
std::string cell_csv(const std::string& unit, double scale) {
  std::ostringstream csv;
  csv << "point,role,robot_x_" << unit << ",robot_y_" << unit << ",robot_z_" << unit
      << ",sensor_x_" << unit << ",sensor_y_" << unit << ",sensor_z_" << unit << "\n";
  auto row = [&](const std::string& name, const char* role, double x, double y, double z) {
    csv << name << "," << role << "," << scale * x << "," << scale * y << "," << scale * z << ","
        << scale * (x + 0.1 + 1e-3 * z * z) << "," << scale * (y - 0.2) << ","
        << scale * (z + 2.0) << "\n";
  };
  for (int i = 0; i < 27; ++i) {
    row("F" + std::to_string(i), "fiducial", 0.3 + 0.05 * (i % 3), 0.05 * (i / 3 % 3),
        0.2 + 0.05 * (i / 9));
  }
  for (int i = 0; i < 8; ++i) {
    row("T" + std::to_string(i), "target", 0.325 + 0.05 * (i % 2), 0.025 + 0.05 * (i / 2 % 2),
        0.225 + 0.05 * (i / 4));
  }
  return csv.str();
}

CliResult report_on(const fs::path& dir, const std::string& csv_text) {
  const fs::path csv = dir / "cell.csv";
  write_text(csv, csv_text);
  const CliResult registered = run_vrreg("register --fiducials " + shell_quoted(csv) + " -o " +
                                         shell_quoted(dir / "model.json"));
  EXPECT_EQ(registered.status, 0) << registered.err;
  return run_vrreg("report --model " + shell_quoted(dir / "model.json") + " --targets " +
                   shell_quoted(csv) + " -o " + shell_quoted(dir / "cell.html"));
}

TEST(PlausibilityWarning, MillimetresInMetreColumnsAreNamed) {
  const fs::path dir = fresh_dir("plausibility-mm-as-m");
  const CliResult r = report_on(dir, cell_csv("m", 1000.0));  // 300 "m" from the robot base
  EXPECT_NE(r.err.find("vrreg: warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cell.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("_mm"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(PlausibilityWarning, PlausibleCellsGetNone) {
  const fs::path dir = fresh_dir("plausibility-ok");
  for (const auto& [unit, scale] : {std::pair<std::string, double>{"m", 1.0}, {"mm", 1000.0}}) {
    const CliResult r = report_on(dir, cell_csv(unit, scale));
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << unit << ": " << r.err;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
