// SPDX-License-Identifier: Apache-2.0
// An arm on a linear axis described by URDF (tests/data/rail_cell.csv, written by
// scripts/make-rail-cell.py: the as-built robot differs from the commanded one in its rail offset,
// skew, scale and bow, link lengths and joint offsets; 0.02 mm tracker noise): it registers with
// --robot FILE.urdf, the joint-space model fits the carriage's error in metres, and evaluate
// corrects targets at carriage positions between the fiducials' to near the noise floor.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

std::string rail_data(const std::string& name) {
  return shell_quoted(std::string(VRREG_TEST_DATA_DIR) + "/" + name);
}

TEST(RailCellCli, JointModelOnAUrdfArmWithAPrismaticAxis) {
  const fs::path dir = fresh_dir("rail_cell");
  const std::string cell = rail_data("rail_cell.csv");
  const std::string robot = rail_data("urdf/ur5_on_rail.urdf");
  const CliResult r = run_vrreg_in(dir, "register --fiducials " + cell + " --robot " + robot +
                                            " --interpolation joint -o j.json");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string& extra : {std::string(), " --robot " + robot}) {
    const CliResult e =
        run_vrreg_in(dir, "evaluate --model j.json --targets " + cell + extra + " --json");
    ASSERT_EQ(e.status, 0) << e.err;
    const nlohmann::json j = nlohmann::json::parse(e.out);
    EXPECT_EQ(j["interpolation"], "joint");
    EXPECT_EQ(j["n_targets"], 30);
    EXPECT_EQ(j["n_flagged"], 0);
    // Uncorrected 0.11 mm; the targets' own reading noise is 0.035 mm (3D).
    EXPECT_GT(j["unc_rms_t_mm"].get<double>(), 0.09);
    EXPECT_LT(j["cor_rms_t_mm"].get<double>(), 0.05);
    EXPECT_GT(j["calibration"]["rms_tre_over_sd"].get<double>(), 0.7);
    EXPECT_LT(j["calibration"]["rms_tre_over_sd"].get<double>(), 1.4);
  }
  // auto compares the methods that apply (position-only fields do not: one location, several
  // carriage positions) and keeps the joint model.
  const CliResult a = run_vrreg_in(dir, "register --fiducials " + cell + " --robot " + robot +
                                            " --interpolation auto -o a.json");
  ASSERT_EQ(a.status, 0) << a.err;
  const nlohmann::json model = nlohmann::json::parse(read_text(dir / "a.json"));
  EXPECT_EQ(model["corrector"]["method"], "joint") << model["corrector"]["cross_validation"].dump();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
