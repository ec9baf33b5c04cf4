// SPDX-License-Identifier: Apache-2.0
// The joint-space model fitted in one arm configuration and asked about another (the base turned
// by about 90 degrees): every point is outside its support, and --extrapolate's sd covers the
// error there (RMS of TRE / sd between 0.5 and 1.5), the registration's tilt included.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

struct Errors {
  int extrapolated = 0;
  int outside = 0;
  double rms_z = 0.0;
};

// status and TRE / predicted sd of every row of a per-target CSV.
Errors errors_of(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  Errors e;
  double sum = 0.0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("point,", 0) == 0) continue;
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    if (f.size() > 2 && f[2] == "outside support") ++e.outside;
    if (f.size() < 13 || f[2] != "extrapolated") continue;
    ++e.extrapolated;
    const double z = std::stod(f[4]) / std::stod(f[12]);
    sum += z * z;
  }
  e.rms_z = e.extrapolated > 0 ? std::sqrt(sum / e.extrapolated) : NAN;
  return e;
}

TEST(JointExtrapolationCli, SdCoversTheErrorInAnotherArmConfiguration) {
  const fs::path dir = fresh_dir("joint_extrapolation");
  write_text(dir / "fitted.csv",
             "point,robot_x_mm,robot_y_mm,robot_z_mm\nA,400,-100,300\nB,450,-50,350\n");
  write_text(dir / "turned.csv", "point,robot_x_mm,robot_y_mm,robot_z_mm\nC,-100,-420,300\n");
  for (const std::string step :
       {"plan --parts fitted.csv --halfwidth-mm 40 --spacing-mm 20 --robot ur5 -o p1.csv",
        "plan --parts turned.csv --halfwidth-mm 20 --spacing-mm 20 --robot ur5 -o p2.csv",
        "simulate ur5 --plan p1.csv --seed 2 -o m1.csv", "simulate ur5 --plan p2.csv --seed 2 -o m2.csv",
        "register --fiducials m1.csv --interpolation joint --robot ur5 -o j.json"}) {
    const CliResult r = run_vrreg_in(dir, step);
    ASSERT_EQ(r.status, 0) << step << "\n" << r.err;
  }
  // The second cell's readings, all as targets.
  std::string targets = read_text(dir / "m2.csv");
  for (std::size_t at = 0; (at = targets.find(",fiducial,", at)) != std::string::npos;) {
    targets.replace(at, 10, ",target,");
  }
  write_text(dir / "t2.csv", targets);
  ASSERT_EQ(run_vrreg_in(dir, "evaluate --model j.json --targets t2.csv --per-target plain.csv").status, 0);
  const Errors plain = errors_of(read_text(dir / "plain.csv"));
  EXPECT_GT(plain.outside, 50);
  EXPECT_EQ(plain.extrapolated, 0);
  const CliResult e =
      run_vrreg_in(dir, "evaluate --model j.json --targets t2.csv --extrapolate --per-target e.csv");
  ASSERT_EQ(e.status, 0) << e.err;
  const Errors far = errors_of(read_text(dir / "e.csv"));
  EXPECT_EQ(far.extrapolated, plain.outside);
  EXPECT_GE(far.rms_z, 0.5);
  EXPECT_LE(far.rms_z, 1.5);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
