// SPDX-License-Identifier: Apache-2.0
// Field models as a user runs them : evaluate --interpolation auto prints the
// cross-validation table and the predicted sd with its calibration, register --interpolation
// auto stores the choice, the CSVs gain predicted_sd_mm, the same input gives the same bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

class FieldModelCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    cell_ = (fs::path(VRREG_SOURCE_DIR) / "examples/data/example-cell.csv").string();
    ASSERT_EQ(run_vrreg_in(dir_, "register --fiducials " + cell_ + " -o m.json").status, 0);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::string cell_;
};

TEST_F(FieldModelCli, TrilinearWritesPredictedSdAndTheSameBytesTwice) {
  const std::string args = "evaluate --model m.json --targets " + cell_ +
                           " --interpolation trilinear --per-target pt.csv --json";
  const CliResult a = run_vrreg_in(dir_, args);
  ASSERT_EQ(a.status, 0) << a.err;
  const std::string first = read_text(dir_ / "pt.csv");
  const CliResult b = run_vrreg_in(dir_, args);
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(first, read_text(dir_ / "pt.csv"));
  EXPECT_NE(first.find(",predicted_sd_mm\n"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(a.out);
  EXPECT_EQ(j["interpolation"], "trilinear");
  EXPECT_GT(j["predicted_sd_median_mm"].get<double>(), 0.0);
  EXPECT_GT(j["calibration"]["rms_tre_over_sd"].get<double>(), 0.7);
  EXPECT_LT(j["calibration"]["rms_tre_over_sd"].get<double>(), 1.3);
  const CliResult c = run_vrreg_in(
      dir_, "correct --model m.json --points " + cell_ + " --interpolation trilinear -o c.csv");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(read_text(dir_ / "c.csv").find(",predicted_sd_mm\n"), std::string::npos);
  EXPECT_NE(c.out.find("predicted sd (1 sigma, 3D)"), std::string::npos) << c.out;
}

TEST_F(FieldModelCli, AutoPrintsTheTableAndRegisterStoresTheChoice) {
  if (std::getenv("VRREG_SANITIZED") != nullptr) GTEST_SKIP() << "kriging is slow under ASan";
  const CliResult e =
      run_vrreg_in(dir_, "evaluate --model m.json --targets " + cell_ + " --interpolation auto");
  ASSERT_EQ(e.status, 0) << e.err;
  for (const char* s : {"cross-validation              5 folds", "scattered", "trilinear", "rbf",
                        "kriging", "joint        not applicable: the fiducials have no joint",
                        "<- chosen", "calibration of sigma_pred"}) {
    EXPECT_NE(e.out.find(s), std::string::npos) << s << "\n" << e.out;
  }
  const CliResult r = run_vrreg_in(
      dir_, "register --fiducials " + cell_ + " --interpolation auto -o auto.json --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const std::string chosen = j["cross_validation"]["chosen"];
  EXPECT_EQ(j["interpolation"], chosen);
  EXPECT_NE(chosen, "auto");
  const nlohmann::json model = nlohmann::json::parse(read_text(dir_ / "auto.json"));
  EXPECT_EQ(model["interpolation"]["method"], chosen);
}

// A field model says "outside support" of a point a metre from its fiducials and leaves it
// uncorrected; --extrapolate corrects it, "extrapolated", with a wider sd than inside.
TEST_F(FieldModelCli, FarPointsAreOutsideSupportUnlessExtrapolateIsAsked) {
  ASSERT_EQ(run_vrreg_in(dir_, "register --fiducials " + cell_ + " --interpolation rbf -o r.json")
                .status,
            0);
  write_text(dir_ / "p.csv",
             "point,role,sensor_x_mm,sensor_y_mm,sensor_z_mm\n"
             "IN,target,247.03213594049433,647.2465665636704,2091.6156169529377\n"
             "FAR,target,1247.03213594049433,647.2465665636704,2091.6156169529377\n");
  const CliResult plain = run_vrreg_in(dir_, "correct --model r.json --points p.csv -o c.csv --json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(nlohmann::json::parse(plain.out)["n_flagged"], 1) << plain.out;
  const std::string flagged = read_text(dir_ / "c.csv");
  EXPECT_NE(flagged.find("\nIN,,ok,"), std::string::npos) << flagged;
  EXPECT_NE(flagged.find("\nFAR,,outside support,"), std::string::npos) << flagged;
  const CliResult far =
      run_vrreg_in(dir_, "correct --model r.json --points p.csv -o e.csv --json --extrapolate");
  ASSERT_EQ(far.status, 0) << far.err;
  EXPECT_EQ(nlohmann::json::parse(far.out)["n_flagged"], 0) << far.out;
  const std::string extrapolated = read_text(dir_ / "e.csv");
  EXPECT_NE(extrapolated.find("\nFAR,,extrapolated,"), std::string::npos) << extrapolated;
}

TEST_F(FieldModelCli, JointWithoutJointsOrRobotSaysWhy) {
  const CliResult e =
      run_vrreg_in(dir_, "evaluate --model m.json --targets " + cell_ + " --interpolation joint");
  EXPECT_EQ(e.status, 1);
  EXPECT_NE(e.err.find("no joint angles"), std::string::npos) << e.err;
  EXPECT_EQ(e.err.find('\n'), e.err.size() - 1) << e.err;  // one line
}

// A saved kriging corrector whose file was edited is refused where it is loaded, by every
// command and the service alike, in one line naming the model file and the key.
TEST_F(FieldModelCli, AnEditedKrigingModelIsRefusedWhenLoaded) {
  if (std::getenv("VRREG_SANITIZED") != nullptr) GTEST_SKIP() << "kriging is slow under ASan";
  ASSERT_EQ(
      run_vrreg_in(dir_, "register --fiducials " + cell_ + " --interpolation kriging -o k.json")
          .status,
      0);
  const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(read_text(dir_ / "k.json"));
  const auto expect_refused = [&](const nlohmann::ordered_json& edited, const std::string& key) {
    write_text(dir_ / "edited.json", edited.dump(2));
    for (const std::string& args :
         {"evaluate --model edited.json --targets " + cell_ + " --exact",
          "correct --model edited.json --points " + cell_ + " -o c.csv",
          std::string("serve --listen 127.0.0.1:0 --reload-poll-ms 0 --model cell=edited.json")}) {
      const CliResult r = run_vrreg_in(dir_, args, "timeout 60");
      EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
      EXPECT_NE(r.err.find("edited.json: '" + key + "'"), std::string::npos) << args << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "c.csv"));
  };
  for (const char* label : {"rbf", "joint"}) {
    nlohmann::ordered_json edited = doc;
    edited["corrector"]["method"] = label;
    expect_refused(edited, "corrector.method");
  }
  nlohmann::ordered_json edited = doc;
  edited["corrector"]["state"]["x.length_m"]["values"][0] = -0.05;
  expect_refused(edited, "corrector.state.x.length_m");
  edited = doc;
  edited["corrector"]["state"]["x.signal_sd_m"] =
      1000.0 * doc["corrector"]["state"]["x.signal_sd_m"].get<double>();
  expect_refused(edited, "corrector.state");
}

}  // namespace
}  // namespace vrreg::testing
