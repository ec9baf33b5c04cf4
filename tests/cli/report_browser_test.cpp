// SPDX-License-Identifier: Apache-2.0
// The browser test: `vrreg report` pages rendered in headless Chromium (Debian's
// chromium, driven by playwright-core from web/ through tests/browser/check_report.mjs), as a
// reader would open them: every chart drawn, with title, caption and axis titles; no console
// error; no request leaving the machine. Screenshots are kept in <build>/browser-screenshots/.
// Without Chromium, Node.js or playwright-core the test FAILS, naming the setup command.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

const std::string kSource = VRREG_SOURCE_DIR;

fs::path screenshot_dir() {
  const fs::path dir = fs::path(VRREG_CLI_PATH).parent_path().parent_path() / "browser-screenshots";
  fs::create_directories(dir);
  return dir;
}

std::string chromium_path() {
  const char* env = std::getenv("VRREG_CHROMIUM");
  return env && *env ? env : "/usr/bin/chromium";
}

// What is missing to run the check, as a message; empty when all is there.
std::string missing_tools() {
  if (!fs::exists(chromium_path())) {
    return "Chromium is missing at " + chromium_path() +
           ": run scripts/install-deps.sh (apt-get install chromium) or set VRREG_CHROMIUM";
  }
  if (std::system("command -v node >/dev/null 2>&1") != 0) {
    return "Node.js (node) is missing: run scripts/install-deps.sh";
  }
  if (!fs::exists(kSource + "/web/node_modules/playwright-core/index.mjs")) {
    return "web/node_modules/playwright-core is missing: run scripts/install-deps.sh (npm ci in "
           "web/)";
  }
  return "";
}

struct Check {
  int status = -1;
  std::string out;
  std::string err;
};

// node check_report.mjs HTML PNG CHARTS
Check check_in_browser(const fs::path& html, const fs::path& png, int charts, const fs::path& dir) {
  const std::string command = "node '" + kSource + "/tests/browser/check_report.mjs' '" +
                              html.string() + "' '" + png.string() + "' " + std::to_string(charts) +
                              " >'" + (dir / "check.out").string() + "' 2>'" +
                              (dir / "check.err").string() + "' </dev/null";
  const int raw = std::system(command.c_str());
  Check c;
  c.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  c.out = read_text(dir / "check.out");
  c.err = read_text(dir / "check.err");
  return c;
}

class ReportBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Writes the report with `args`, renders it, and checks what the reader sees.
  void render(const std::string& args, const std::string& name) {
    const std::string missing = missing_tools();
    ASSERT_TRUE(missing.empty()) << missing;
    const fs::path html = dir_ / (name + ".html");
    const CliResult r = run_vrreg("report " + args + " -o '" + html.string() + "' --json");
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    const int charts = nlohmann::json::parse(r.out)["charts"].get<int>();
    EXPECT_GE(charts, 4);
    const fs::path png = screenshot_dir() / (name + ".png");
    const Check c = check_in_browser(html, png, charts, dir_);
    ASSERT_EQ(c.status, 0) << c.out << c.err;
    const nlohmann::json result = nlohmann::json::parse(c.out);
    EXPECT_TRUE(result["ok"].get<bool>()) << c.out;
    EXPECT_EQ(result["charts"], charts) << c.out;
    EXPECT_TRUE(fs::exists(png) && fs::file_size(png) > 10'000) << png;
    std::printf("screenshot: %s (%d charts)\n", png.c_str(), charts);
  }
  fs::path dir_;
};

TEST_F(ReportBrowser, CellReportRendersEveryChart) {
  const std::string model = (dir_ / "model.json").string();
  ASSERT_EQ(run_vrreg("register --fiducials '" + kExampleCell + "' -o '" + model + "'").status, 0);
  render("--model '" + model + "' --targets '" + kExampleCell + "' --sigma-rep-mm 0.1",
         "cell-report");
}

TEST_F(ReportBrowser, ReproduceReportRendersEveryFigureAndThePlan) {
  const std::string out = (dir_ / "reproduce").string();
  const CliResult rep = run_vrreg("reproduce --out '" + out + "' --quiet");
  ASSERT_EQ(rep.status, 0) << rep.err;
  const std::string parts = (dir_ / "parts.csv").string();
  write_text(parts,
             "point,robot_x_mm,robot_y_mm,robot_z_mm\n"
             "hole_A,420,-140,250\nhole_B,480,-140,250\npin_C,480,-60,260\npin_D,420,-60,240\n");
  const std::string plan = (dir_ / "plan.csv").string();
  const CliResult p = run_vrreg("plan --parts '" + parts +
                                "' --halfwidth-mm 10 --spacing-mm 5 --robot ur5 -o '" + plan + "'");
  ASSERT_EQ(p.status, 0) << p.err;
  render("--reproduce '" + out + "' --plan '" + plan + "'", "reproduce-report");
}

}  // namespace
}  // namespace vrreg::testing
