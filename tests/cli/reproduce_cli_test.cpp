// SPDX-License-Identifier: Apache-2.0
// `vrreg reproduce` as a user runs it: the tables beside the paper's, the findings, the figure data
// written atomically into --out, the --json shape (= reproduce.json), several seeds as mean +- sd,
// and no progress bar when stderr is not a terminal.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "vrreg_test.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class ReproduceCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string out_dir() const { return (dir_ / "out").string(); }
  fs::path dir_;
};

TEST_F(ReproduceCli, PrintsTablesBesideThePaperAndWritesTheFigureData) {
  const CliResult r = run_vrreg("reproduce --out '" + out_dir() + "'");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("vrreg reproduce: seed 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Table 2. KUKA LWR 4+"), std::string::npos);
  EXPECT_NE(r.out.find("(0.977)"), std::string::npos) << "paper's sigma_L beside ours";
  EXPECT_NE(r.out.find("Findings of the paper"), std::string::npos);
  EXPECT_NE(r.out.find("Table 1. UR5"), std::string::npos);
  EXPECT_NE(r.out.find("Figures 7 and 8"), std::string::npos);
  EXPECT_EQ(r.out.find("NOT MET"), std::string::npos) << r.out;
  // stderr is a file here: no progress bar, only the timing line.
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  EXPECT_NE(r.err.find("reproduce: 1 seed in"), std::string::npos) << r.err;
  for (const char* name :
       {"table1.csv", "figure7_8.csv", "figure10_targets.csv", "figure11_delta_tre.csv",
        "table2.csv", "histograms_l.csv", "tre_per_target.csv", "reproduce.json"}) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / name)) << name;
  }
  EXPECT_TRUE(read_text(dir_ / "out" / "table2.csv").starts_with("config,strategy,sigma_l_mm,"));
  // The HTML report beside the figure data, named in the output.
  EXPECT_NE(r.out.find("HTML report (opens offline in a browser): " + out_dir() + "/report.html"),
            std::string::npos)
      << r.out;
  EXPECT_NE(read_text(dir_ / "out" / "report.html").find("<html"), std::string::npos);
  const json written = json::parse(read_text(dir_ / "out" / "reproduce.json"));
  const CliResult again =
      run_vrreg("reproduce --json --quiet --out '" + (dir_ / "again").string() + "'");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_TRUE(again.err.empty()) << again.err;
  EXPECT_EQ(json::parse(again.out), written)
      << "--json prints reproduce.json; same seed, same data";
}

TEST_F(ReproduceCli, WithoutTheChartingLibraryTheDataStandAlone) {
  const CliResult r = run_vrreg_in({}, "reproduce --only lwr4 --out '" + out_dir() + "'",
                                   "VRREG_PLOTLY_JS=/nonexistent/plotly.js");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("reproduce: no HTML report: the Plotly library is missing"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "reproduce.json"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "report.html"));
  const CliResult skipped = run_vrreg("reproduce --only lwr4 --no-report --quiet --out '" +
                                      (dir_ / "skipped").string() + "'");
  ASSERT_EQ(skipped.status, 0) << skipped.err;
  EXPECT_TRUE(skipped.err.empty()) << skipped.err;
  EXPECT_FALSE(fs::exists(dir_ / "skipped" / "report.html"));
}

TEST_F(ReproduceCli, JsonShape) {
  const CliResult r = run_vrreg("reproduce --json --quiet --out ''");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["seed"], 1);
  EXPECT_EQ(j["seeds"], json::array({1}));
  ASSERT_TRUE(j["table2"].is_array());
  ASSERT_EQ(j["table2"].size(), 12u);
  for (const json& row : j["table2"]) {
    for (const char* key : {"config", "strategy", "sigma_l_mm", "rho", "unc_rms_t_mm",
                            "cor_rms_t_mm", "gamma_percent"}) {
      EXPECT_TRUE(row.contains(key)) << key;
    }
    EXPECT_TRUE(row["config"].is_number_integer());
    EXPECT_EQ(row["sigma_l_mm"].is_null(), row["strategy"] == 3);
  }
  EXPECT_EQ(j["findings"].size(), 6u);
  for (const json& f : j["findings"]) {
    for (const char* key : {"id", "statement", "value", "met"}) EXPECT_TRUE(f.contains(key));
  }
  EXPECT_NEAR(j["kuka"]["switched_points_fraction"].get<double>(), 0.164, 0.001);
  for (const char* data : {"A1", "A2"}) {
    for (const char* key :
         {"sigma_opt_mm", "sigma_l_mm", "sigma_noise_mm", "rho", "unc_rms_t_mm", "cor_rms_t_mm",
          "gamma_percent", "n_bad", "n_targets", "n_fiducials", "d_mm"}) {
      EXPECT_TRUE(j["table1"][data].contains(key)) << data << " " << key;
    }
  }
  EXPECT_NEAR(j["table1"]["A1"]["d_mm"].get<double>(), 43.3, 0.01);
  ASSERT_EQ(j["figure7"].size(), 10u);
  for (const json& p : j["figure7"]) {
    for (const char* key : {"d_mm", "cor_rms_t_mm", "n_bad"}) EXPECT_TRUE(p.contains(key));
  }
}

TEST_F(ReproduceCli, SeveralSeedsGiveMeanAndSd) {
  if (sanitized()) GTEST_SKIP() << "several seeds twice: release builds only";
  const CliResult r = run_vrreg("reproduce --seed 3 --seeds 2 --json --quiet --out ''");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["seeds"], json::array({3, 4}));
  EXPECT_TRUE(j["table1"]["A1"]["cor_rms_t_mm"].contains("mean"));
  EXPECT_TRUE(j["table1"]["A1"]["cor_rms_t_mm"].contains("sd"));
  EXPECT_TRUE(j["table2"][0]["config"].is_number_integer());
  EXPECT_EQ(j["findings"][0]["n_seeds"], 2);
  const CliResult text = run_vrreg("reproduce --seed 3 --seeds 2 --quiet --out ''");
  EXPECT_NE(text.out.find("seeds 3-4"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(" ± "), std::string::npos);
  EXPECT_NE(text.out.find("met on"), std::string::npos);
}

TEST_F(ReproduceCli, BadArguments) {
  EXPECT_NE(run_vrreg("reproduce --seeds 0").status, 0);
  const std::string blocker = (dir_ / "file").string();
  write_text(blocker, "not a directory");
  const CliResult r = run_vrreg("reproduce --quiet --only lwr4 --out '" + blocker + "/sub'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(blocker), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vrreg::testing
