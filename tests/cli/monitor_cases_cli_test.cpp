// SPDX-License-Identifier: Apache-2.0
// vrreg check and update under what a plant meets, on a simulated UR5 cell planned with the
// default 4 monitor points: --time checked as ISO 8601, a monitor file named with a comma in the
// history, two checks appending at once, an update after a check that found nothing refused,
// a noisier day (exit 13), two monitors read after a bump (exit 10, saying what they cannot
// tell), a model without monitors named in the error, a warm-up and a bump told by the history.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/io/measurement_csv_writer.hpp"
#include "vrreg/io/monitor_json.hpp"

namespace vrreg::testing::monitor_cases_cli_test {
namespace {

namespace fs = std::filesystem;

// A planned cell (4 monitor points by default), simulated with `seed` and registered as cell.json.
fs::path planned_cell(const std::string& name, int seed = 5) {
  const fs::path dir = fresh_dir(name);
  write_text(dir / "parts.csv", "point,robot_x_mm,robot_y_mm,robot_z_mm\nP1,-400,-100,300\n");
  EXPECT_EQ(run_vrreg_in(dir,
                         "plan --parts parts.csv --robot ur5 --halfwidth-mm 100 --spacing-mm 50 "
                         "--monitor -o plan.csv")
                .status,
            0);
  const std::string s = std::to_string(seed);
  EXPECT_EQ(run_vrreg_in(dir, "simulate ur5 --plan plan.csv --seed " + s + " -o cell.csv").status,
            0);
  EXPECT_EQ(run_vrreg_in(dir, "register --fiducials cell.csv -o cell.json").status, 0);
  return dir;
}

// The monitors read again (`later`: simulate's options for when and what happened).
void read_monitors(const fs::path& dir, const std::string& out, const std::string& later,
                   int seed = 5) {
  const CliResult r =
      run_vrreg_in(dir, "simulate ur5 --plan plan.csv --seed " + std::to_string(seed) +
                            " --only monitor -o '" + out + "' " + later);
  ASSERT_EQ(r.status, 0) << r.err;
}

// `in` written to `out` one row per location (visit), keeping those `keep` says, each moved by
// `extra_sd_m` more noise per axis.
void rewrite_rows(const fs::path& in, const fs::path& out, double extra_sd_m,
                  const std::function<bool(const Location&)>& keep) {
  const MeasurementSet set = io::read_measurement_csv(in.string());
  Random rng(29);
  std::vector<io::Reading> rows;
  for (const Location& l : set.locations) {
    if (!keep(l)) continue;
    io::Reading r;
    r.point = l.point;
    r.role = l.role;
    r.robot_m = l.robot_m;
    r.sensor_m = l.sensor_m + rng.normal3(extra_sd_m);
    r.config = l.config;
    r.visit = l.visit;
    rows.push_back(r);
  }
  io::write_measurement_csv(out.string(), rows);
}

bool every_row(const Location&) { return true; }

TEST(MonitorCasesCli, TimeIsIso8601AndAFileNameWithACommaIsQuoted) {
  const fs::path dir = planned_cell("monitor_cases_time");
  read_monitors(dir, "to,day.csv", "--at-h 1");
  for (const std::string command : {"check --model cell.json --monitor 'to,day.csv'",
                                    "update --model cell.json --points 'to,day.csv' --change "
                                    "bump -o new.json"}) {
    const CliResult bad = run_vrreg_in(dir, command + " --time 'not a time'");
    EXPECT_EQ(bad.status, 2) << command << bad.err;
    EXPECT_NE(bad.err.find("ISO 8601"), std::string::npos) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
  EXPECT_FALSE(fs::exists(dir / "new.json"));
  const CliResult ok = run_vrreg_in(dir,
                                    "check --model cell.json --monitor 'to,day.csv' --history "
                                    "h.csv --time 2026-11-26T09:00:00+01:00");
  EXPECT_EQ(ok.status, 0) << ok.out << ok.err;
  const std::string history = read_text(dir / "h.csv");
  EXPECT_NE(history.find(",\"to,day.csv\","), std::string::npos) << history;
  const std::vector<io::CheckHistoryRow> rows = io::read_check_history((dir / "h.csv").string());
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].source, "to,day.csv");
  EXPECT_EQ(rows[0].points.size(), 4u);
  const CliResult page =
      run_vrreg_in(dir, "report --model cell.json --targets cell.csv --history h.csv -o r.html");
  EXPECT_EQ(page.status, 0) << page.err;
  fs::remove_all(dir);
}

TEST(MonitorCasesCli, TwoChecksAtOnceBothKeepTheirRows) {
  const fs::path dir = planned_cell("monitor_cases_together");
  read_monitors(dir, "a.csv", "--at-h 1");
  const std::string check = "'" + std::string(VRREG_CLI_PATH) +
                            "' check --model cell.json --monitor a.csv --history "
                            "h.csv --time 2026-11-26T0";
  for (int trial = 0; trial < 8; ++trial) {
    const std::string both = "cd '" + dir.string() + "' && (" + check + "8:00:00Z >/dev/null & " +
                             check + "9:00:00Z >/dev/null & wait)";
    ASSERT_EQ(std::system(both.c_str()), 0);
    EXPECT_EQ(io::read_check_history((dir / "h.csv").string()).size(),
              static_cast<std::size_t>(2 * (trial + 1)));
  }
  fs::remove_all(dir);
}

TEST(MonitorCasesCli, AnUpdateAfterACheckThatFoundNothingIsRefused) {
  const fs::path dir = planned_cell("monitor_cases_update");
  read_monitors(dir, "same.csv", "--at-h 1");
  const CliResult check = run_vrreg_in(
      dir, "check --model cell.json --monitor same.csv --history h.csv --time 2026-11-26T09:00Z");
  ASSERT_EQ(check.status, 0) << check.out;
  const CliResult refused =
      run_vrreg_in(dir, "update --model cell.json --points same.csv --change drift -o new.json");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("no change"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--even-if-unchanged"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "new.json"));
  const CliResult forced =
      run_vrreg_in(dir,
                   "update --model cell.json --points same.csv --change drift -o new.json "
                   "--even-if-unchanged --json");
  EXPECT_EQ(forced.status, 0) << forced.err;
  EXPECT_EQ(nlohmann::json::parse(forced.out)["today_check"]["verdict"], "valid");
  // Fiducials only: nothing to check again; the history's last check of this model decides.
  ASSERT_EQ(run_vrreg_in(dir,
                         "simulate ur5 --plan plan.csv --seed 5 --only fiducial -o f.csv "
                         "--at-h 1")
                .status,
            0);
  const CliResult by_history = run_vrreg_in(
      dir, "update --model cell.json --points f.csv --change bump -o new2.json --history h.csv");
  EXPECT_EQ(by_history.status, 1);
  EXPECT_NE(by_history.err.find("last check of this model found no change"), std::string::npos)
      << by_history.err;
  fs::remove_all(dir);
}

TEST(MonitorCasesCli, ANoisierDayAndTwoMonitorsAfterABumpSayWhatTheyCanTell) {
  const fs::path dir = planned_cell("monitor_cases_noisy");
  // Today: 4 visits, the visits' scatter (0.05 mm) twice as large.
  read_monitors(dir, "short.csv", "--at-h 1 --monitor-visits 4");
  rewrite_rows(dir / "short.csv", dir / "noisy.csv", 0.087e-3, every_row);
  const CliResult noisy = run_vrreg_in(dir, "check --model cell.json --monitor noisy.csv --json");
  EXPECT_EQ(noisy.status, 13) << noisy.out << noisy.err;
  const nlohmann::json j = nlohmann::json::parse(noisy.out);
  EXPECT_EQ(j["verdict"], "noisier today");
  EXPECT_TRUE(j["noise"]["noisier"].get<bool>());
  // Two of the monitors read after a bump: a rigid change, and what two points cannot see.
  read_monitors(dir, "bumped.csv", "--at-h 1 --bump-mm 0.2 --bump-at-h 0.5");
  rewrite_rows(dir / "bumped.csv", dir / "two.csv", 0.0,
               [](const Location& l) { return l.point == "monitor-1" || l.point == "monitor-2"; });
  const CliResult two = run_vrreg_in(dir, "check --model cell.json --monitor two.csv");
  EXPECT_EQ(two.status, 10) << two.out << two.err;
  EXPECT_NE(two.out.find("cannot tell"), std::string::npos) << two.out;
  EXPECT_NE(two.out.find("read with the monitors"), std::string::npos) << two.out;
  EXPECT_EQ(two.out.find("smooth"), std::string::npos) << two.out;
  fs::remove_all(dir);
}

TEST(MonitorCasesCli, ErrorsAboutTheModelsMonitorsNameTheModel) {
  const fs::path dir = planned_cell("monitor_cases_model");
  rewrite_rows(dir / "cell.csv", dir / "plain.csv", 0.0,
               [](const Location& l) { return l.role != Role::kMonitor; });
  ASSERT_EQ(run_vrreg_in(dir, "register --fiducials plain.csv -o plain.json").status, 0);
  read_monitors(dir, "today.csv", "--at-h 1");
  const CliResult r = run_vrreg_in(dir, "check --model plain.json --monitor today.csv");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("plain.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no monitor points"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("today.csv"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(MonitorCasesCli, PlanOffersFourMonitorsOffOnePlaneAndTheCheckTime) {
  const fs::path dir = planned_cell("monitor_cases_plan");
  const std::string plan = read_text(dir / "plan.csv");
  EXPECT_NE(plan.find("monitor-4,monitor,"), std::string::npos);
  EXPECT_EQ(plan.find("monitor-5,monitor,"), std::string::npos);
  const CliResult three = run_vrreg_in(
      dir,
      "plan --parts parts.csv --robot ur5 --halfwidth-mm 100 --spacing-mm 50 --monitor 3 "
      "--json");
  ASSERT_EQ(three.status, 0) << three.err;
  const std::string notes = nlohmann::json::parse(three.out)["notes"].dump();
  EXPECT_NE(notes.find("on one plane"), std::string::npos) << notes;
  EXPECT_NE(notes.find("a check on the robot"), std::string::npos) << notes;
  const CliResult four = run_vrreg_in(
      dir,
      "plan --parts parts.csv --robot ur5 --halfwidth-mm 100 --spacing-mm 50 --monitor "
      "--json");
  ASSERT_EQ(four.status, 0) << four.err;
  EXPECT_EQ(nlohmann::json::parse(four.out)["notes"].dump().find("on one plane"),
            std::string::npos);
  fs::remove_all(dir);
}

TEST(MonitorCasesCli, TheHistoryTellsAWarmUpFromABump) {
  const fs::path dir = planned_cell("monitor_cases_onset", 1);
  // A warm-up (links +1e-3 at full, tau 30 min), checked at 2 and 4 min.
  const std::string warm = "--warmup-growth 1e-3 --warmup-tau-h 0.5";
  read_monitors(dir, "w2.csv", "--at-h 0.0333333 " + warm, 1);
  read_monitors(dir, "w4.csv", "--at-h 0.0666667 " + warm, 1);
  ASSERT_EQ(run_vrreg_in(dir,
                         "check --model cell.json --monitor w2.csv --history w.csv --time "
                         "2026-11-26T08:02:00Z")
                .status,
            0);
  const CliResult alone = run_vrreg_in(dir, "check --model cell.json --monitor w4.csv");
  EXPECT_EQ(alone.status, 10) << alone.out;  // rigid at the monitor points so far
  const CliResult told = run_vrreg_in(
      dir, "check --model cell.json --monitor w4.csv --history w.csv --time 2026-11-26T08:04:00Z");
  EXPECT_EQ(told.status, 11) << told.out;
  EXPECT_NE(told.out.find("grew over"), std::string::npos) << told.out;
  // A bump between checks: at once.
  read_monitors(dir, "b2.csv", "--at-h 0.0333333", 1);
  read_monitors(dir, "b6.csv", "--at-h 0.1 --bump-mm 0.1 --bump-at-h 0.08", 1);
  ASSERT_EQ(run_vrreg_in(dir,
                         "check --model cell.json --monitor b2.csv --history b.csv --time "
                         "2026-11-26T08:02:00Z")
                .status,
            0);
  const CliResult bump = run_vrreg_in(
      dir, "check --model cell.json --monitor b6.csv --history b.csv --time 2026-11-26T08:06:00Z");
  EXPECT_EQ(bump.status, 10) << bump.out;
  EXPECT_NE(bump.out.find("came at once"), std::string::npos) << bump.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing::monitor_cases_cli_test
