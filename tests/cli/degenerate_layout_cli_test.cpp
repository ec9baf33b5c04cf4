// SPDX-License-Identifier: Apache-2.0
// Layouts that support no interpolation are answered, not refused: nine fiducials in a plane
// register, and evaluate and correct with `linear` or `scattered` leave every point uncorrected,
// flagged "flat layout". A coordinate out of range (1e308 mm: finite, but its square overflows)
// is refused as read, in one line naming the file, line, point and column.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Nine fiducials on a 3 x 3 grid at 25 mm in the plane z = 300 mm, the sensor 1 m away along x
// with small errors, and three targets (one off the plane).
const std::string kFlatCell =
    "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n"
    "F00,fiducial,400,-100,300,-600.01,-100,300.02\n"
    "F01,fiducial,425,-100,300,-575,-99.98,300\n"
    "F02,fiducial,450,-100,300,-550.02,-100.01,300\n"
    "F10,fiducial,400,-75,300,-600,-75.02,299.99\n"
    "F11,fiducial,425,-75,300,-575.01,-75,300.01\n"
    "F12,fiducial,450,-75,300,-550,-74.99,300\n"
    "F20,fiducial,400,-50,300,-599.99,-50,300\n"
    "F21,fiducial,425,-50,300,-575,-50.01,299.98\n"
    "F22,fiducial,450,-50,300,-550.01,-50,300.02\n"
    "T1,target,412.5,-87.5,300,-587.5,-87.49,300.01\n"
    "T2,target,430,-70,310,-570.01,-70,310\n"
    "T3,target,400,-100,350,-600,-100.02,350\n";

TEST(DegenerateLayoutCli, NineCoplanarFiducialsAreAnsweredFlatLayout) {
  const fs::path dir = fresh_dir("degenerate_flat");
  write_text(dir / "cell.csv", kFlatCell);
  for (const std::string method : {"linear", "scattered"}) {
    const CliResult reg = run_vrreg_in(
        dir, "register --fiducials cell.csv --interpolation " + method + " -o m.json");
    ASSERT_EQ(reg.status, 0) << method << ": " << reg.err;
    const CliResult eval =
        run_vrreg_in(dir, "evaluate --model m.json --targets cell.csv --json --per-target t.csv");
    ASSERT_EQ(eval.status, 0) << method << ": " << eval.err;
    const json e = json::parse(eval.out);
    EXPECT_EQ(e["n_targets"].get<int>(), 3) << method;
    EXPECT_EQ(e["n_flagged"].get<int>(), 3) << method;
    EXPECT_NE(e["layout"].get<std::string>().find("lie in a plane or on a line"),
              std::string::npos)
        << e["layout"];
    const std::string per_target = read_text(dir / "t.csv");
    EXPECT_NE(per_target.find("T3,,flat layout,"), std::string::npos) << per_target;
    const CliResult text = run_vrreg_in(dir, "evaluate --model m.json --targets cell.csv");
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("3 targets (flat layout"), std::string::npos) << text.out;
    const CliResult cor = run_vrreg_in(dir, "correct --model m.json --points cell.csv -o c.csv");
    ASSERT_EQ(cor.status, 0) << method << ": " << cor.err;
    EXPECT_NE(read_text(dir / "c.csv").find("flat layout"), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(DegenerateLayoutCli, AnOutOfRangeCoordinateIsOneLineNamingThePoint) {
  const fs::path dir = fresh_dir("degenerate_range");
  std::string cell = kFlatCell;
  const std::string row = "F11,fiducial,425,-75,300,";
  cell.replace(cell.find(row), row.size(), "F11,fiducial,1e308,-75,300,");
  write_text(dir / "cell.csv", cell);
  const CliResult reg = run_vrreg_in(dir, "register --fiducials cell.csv -o m.json");
  EXPECT_NE(reg.status, 0);
  EXPECT_FALSE(fs::exists(dir / "m.json"));
  EXPECT_EQ(reg.err.find('\n'), reg.err.size() - 1) << "one line: " << reg.err;
  for (const char* part : {"cell.csv:6", "F11", "robot_x_mm", "out of range"}) {
    EXPECT_NE(reg.err.find(part), std::string::npos) << part << " in: " << reg.err;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
