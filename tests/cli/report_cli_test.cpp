// SPDX-License-Identifier: Apache-2.0
// `vrreg report` as a user runs it: one self-contained HTML file with a verdict for their cell,
// the same bytes for the same input, labels that cannot inject script, clear one-line errors
// (missing Plotly, missing reproduce.json, wrong options) and no file left on failure.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class ReportCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    model_ = (dir_ / "model.json").string();
    html_ = (dir_ / "cell.html").string();
  }
  void TearDown() override { fs::remove_all(dir_); }
  void register_cell(const std::string& csv) {
    const CliResult r = run_vrreg("register --fiducials '" + csv + "' -o '" + model_ + "'");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  fs::path dir_;
  std::string model_;
  std::string html_;
};

TEST_F(ReportCli, CellReportIsOneOfflineFileWithAVerdict) {
  register_cell(kExampleCell);
  const CliResult r = run_vrreg("report --model '" + model_ + "' --targets '" + kExampleCell +
                                "' --sigma-rep-mm 0.1 -o '" + html_ + "' --json");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  // L histogram, TRE per target, Delta TRE histogram, 3D volume (no configurations here).
  EXPECT_EQ(j["charts"], 4);
  ASSERT_GE(j["verdict"].size(), 3u);
  EXPECT_NE(j["verdict"][0].get<std::string>().find("> 2.5"), std::string::npos) << j.dump(2);
  EXPECT_NE(j["verdict"][1].get<std::string>().find("RRBC lowered RMS_T"), std::string::npos);
  EXPECT_NE(j["verdict"][2].get<std::string>().find("N_bad = "), std::string::npos);

  const std::string html = read_text(html_);
  EXPECT_TRUE(html.starts_with("<!DOCTYPE html>"));
  EXPECT_NE(html.find("data-charts-expected=\"4\""), std::string::npos);
  EXPECT_GT(html.size(), 1'000'000u);    // Plotly is inlined
  EXPECT_EQ(count(html, "<script"), 3);  // figures, library, page: none with src
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);

  // Same input, same bytes.
  const std::string again = (dir_ / "again.html").string();
  ASSERT_EQ(run_vrreg("report --model '" + model_ + "' --targets '" + kExampleCell +
                      "' --sigma-rep-mm 0.1 -o '" + again + "'")
                .status,
            0);
  EXPECT_TRUE(read_text(again) == html);
}

TEST_F(ReportCli, TableSummaryNamesTheFileAndChartCount) {
  register_cell(kExampleCell);
  const CliResult r = run_vrreg("report --model '" + model_ + "' --targets '" + kExampleCell +
                                "' -o '" + html_ + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("report with 4 charts written to " + html_), std::string::npos) << r.out;
  // No repeatability given: sigma_noise comes from the repeat readings alone.
  EXPECT_NE(r.out.find("ρ = σ_L / σ_noise"), std::string::npos) << r.out;
}

TEST_F(ReportCli, PointLabelsCannotInjectScript) {
  // The example cell with one target renamed to a script tag.
  std::string text = read_text(kExampleCell);
  const std::string evil = "T1-1-1</script><script>alert(1)</script>";
  for (std::size_t at = text.find("T1-1-1,"); at != std::string::npos;
       at = text.find("T1-1-1,", at + evil.size())) {
    text.replace(at, 6, evil);
  }
  const std::string csv = (dir_ / "evil.csv").string();
  write_text(csv, text);
  register_cell(csv);
  const CliResult r =
      run_vrreg("report --model '" + model_ + "' --targets '" + csv + "' -o '" + html_ + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string html = read_text(html_);
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_EQ(count(html, "</script>"), 3);
  EXPECT_NE(html.find("T1-1-1\\u003c/script\\u003e"), std::string::npos);
}

TEST_F(ReportCli, MissingPlotlyIsOneLineNamingThePathAndTheSetupCommand) {
  register_cell(kExampleCell);
  ::setenv("VRREG_PLOTLY_JS", "/nonexistent/plotly.min.js", 1);
  const CliResult r = run_vrreg("report --model '" + model_ + "' --targets '" + kExampleCell +
                                "' -o '" + html_ + "'");
  ::unsetenv("VRREG_PLOTLY_JS");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/nonexistent/plotly.min.js"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("scripts/install-deps.sh"), std::string::npos) << r.err;
  EXPECT_EQ(count(r.err, "\n"), 1) << r.err;
  EXPECT_FALSE(fs::exists(html_));
}

TEST_F(ReportCli, ReproduceDirectoryWithoutReproduceJsonIsNamed) {
  const CliResult r = run_vrreg("report --reproduce '" + dir_.string() + "' -o '" + html_ + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find((dir_ / "reproduce.json").string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("vrreg reproduce --out"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(html_));
}

TEST_F(ReportCli, ReproduceReportDrawsWhatTheFileHolds) {
  write_text(dir_ / "reproduce.json", R"({"format": "vrreg-reproduce", "version": 1,
    "table1": {"A1": {"d_mm": 43.3, "gamma_percent": 60}, "A2": {"d_mm": 21.6, "gamma_percent": 70}},
    "figure7": [{"d_mm": 43.3, "cor_rms_t_mm": 0.25, "n_bad": 17},
                {"d_mm": 4.33, "cor_rms_t_mm": 0.11, "n_bad": 4}]})");
  const CliResult r =
      run_vrreg("report --reproduce '" + dir_.string() + "' -o '" + html_ + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["charts"], 2);  // Fig. 7 and 8
  EXPECT_NE(j["verdict"].back().get<std::string>().find("so not drawn"), std::string::npos);

  write_text(dir_ / "reproduce.json", R"({"format": "vrreg-model"})");
  const CliResult bad = run_vrreg("report --reproduce '" + dir_.string() + "' -o '" + html_ + "'");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("reproduce.json: format is \"vrreg-model\""), std::string::npos)
      << bad.err;
}

TEST_F(ReportCli, OptionsSayWhichReport) {
  register_cell(kExampleCell);
  EXPECT_EQ(run_vrreg("report -o '" + html_ + "'").status, 1);
  const CliResult both = run_vrreg("report --model '" + model_ + "' --targets '" + kExampleCell +
                                   "' --reproduce '" + dir_.string() + "' -o '" + html_ + "'");
  EXPECT_EQ(both.status, 1);
  EXPECT_NE(both.err.find("either --model and --targets"), std::string::npos) << both.err;
  EXPECT_EQ(run_vrreg("report --model '" + model_ + "' -o '" + html_ + "'").status, 1);
  EXPECT_EQ(run_vrreg("report --model '" + model_ + "' --targets '" + kExampleCell + "'").status,
            2);
  EXPECT_FALSE(fs::exists(html_));
}

TEST_F(ReportCli, UnwritableOutputLeavesNothing) {
  register_cell(kExampleCell);
  const std::string out = (dir_ / "no" / "such" / "dir" / "cell.html").string();
  const CliResult r = run_vrreg("report --model '" + model_ + "' --targets '" + kExampleCell +
                                "' -o '" + out + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace vrreg::testing
