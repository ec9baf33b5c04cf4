// SPDX-License-Identifier: Apache-2.0
// A cell's check history: ISO 8601 times checked against the C library's own conversion, file
// names with commas and quotes quoted and read back, each point's move kept, the first format
// still read and appended to, rows appended by threads at once all kept whole, and only regular
// files appended to.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <ctime>
#include <filesystem>
#include <fstream>
#include <thread>

#include "vrreg/core/file_error.hpp"
#include "vrreg/io/monitor_json.hpp"

namespace vrreg::io::check_history_test {
namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("vrreg_check_history_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The seconds timegm gives the same fields.
double c_library_s(int year, int month, int day, int hour, int minute, int second) {
  std::tm t{};
  t.tm_year = year - 1900;
  t.tm_mon = month - 1;
  t.tm_mday = day;
  t.tm_hour = hour;
  t.tm_min = minute;
  t.tm_sec = second;
  return static_cast<double>(::timegm(&t));
}

TEST(CheckHistoryTime, Iso8601AsTheCLibraryReadsIt) {
  EXPECT_EQ(parse_iso8601_s("2026-11-26T08:00:00Z"), c_library_s(2026, 11, 26, 8, 0, 0));
  EXPECT_EQ(parse_iso8601_s("2026-11-26"), c_library_s(2026, 11, 26, 0, 0, 0));
  EXPECT_EQ(parse_iso8601_s("2026-11-26T08:05"), c_library_s(2026, 11, 26, 8, 5, 0));
  EXPECT_EQ(parse_iso8601_s("2024-02-29T23:59:59+02:00"), c_library_s(2024, 2, 29, 21, 59, 59));
  EXPECT_EQ(parse_iso8601_s("1969-12-31T23:00:00-0130"), c_library_s(1970, 1, 1, 0, 30, 0));
  EXPECT_EQ(parse_iso8601_s("2000-03-01T00:00:00+05"), c_library_s(2000, 2, 29, 19, 0, 0));
  EXPECT_NEAR(*parse_iso8601_s("2026-11-26T08:00:00.25Z") - c_library_s(2026, 11, 26, 8, 0, 0),
              0.25, 1e-6);
  for (const char* bad :
       {"not a time", "", "2026-11-26T08:00:00Zx", "2026-13-01", "2025-02-29", "2026-11-31",
        "2026-11-26T24:00", "2026-11-26T08:60", "2026-11-26 08:00", "26-11-2026", "2026-11-26T8:00",
        "2026-11-26T08:00:00.", "2026-11-26T08:00:00+2", "2026-11-26T08:00:00+02:0"}) {
    EXPECT_FALSE(parse_iso8601_s(bad)) << bad;
  }
  EXPECT_TRUE(parse_iso8601_s(utc_now()));
}

CheckResult a_check(MonitorVerdict verdict, double moved_m) {
  CheckResult r;
  r.statistics.verdict = verdict;
  r.statistics.change_rms_m = moved_m;
  r.model_id = "00000000000000ab";
  for (const char* name : {"monitor-1", "m 2;x@y"}) {
    MonitorPointCheck p;
    p.point = name;
    p.difference_m = Eigen::Vector3d(moved_m, -moved_m, 0.5 * moved_m);
    p.today_mean_sd_m = 7e-6;
    r.points.push_back(p);
  }
  r.points[1].config = 3;
  return r;
}

TEST(CheckHistoryFile, NamesWithCommasAndEachPointReadBack) {
  const fs::path dir = fresh("names");
  const std::string path = (dir / "h.csv").string();
  append_check_history(path, "2026-11-26T08:00:00Z", "a,b \"c\".csv",
                       a_check(MonitorVerdict::kValid, 1e-5));
  append_check_history(path, "2026-11-26T09:00:00Z", "plain.csv",
                       a_check(MonitorVerdict::kNoisier, 2e-5));
  const std::vector<CheckHistoryRow> rows = read_check_history(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].source, "a,b \"c\".csv");
  EXPECT_EQ(rows[1].verdict, "noisier today");
  EXPECT_EQ(rows[0].model_id, "00000000000000ab");
  ASSERT_EQ(rows[0].points.size(), 2u);
  EXPECT_EQ(rows[0].points[1].point, "m 2;x@y");
  EXPECT_EQ(rows[0].points[1].config, 3);
  EXPECT_NEAR(rows[0].points[1].moved_mm.y(), -0.01, 1e-9);
  EXPECT_NEAR(rows[0].points[1].mean_sd_mm, 0.007, 1e-9);
  // The earlier checks of the model, before a time.
  const std::vector<EarlierCheck> earlier =
      earlier_checks(rows, "00000000000000ab", "2026-11-26T08:30:00Z");
  ASSERT_EQ(earlier.size(), 1u);
  EXPECT_EQ(earlier[0].points[0].point, "monitor-1");
  EXPECT_NEAR(earlier[0].points[0].difference_m.x(), 1e-5, 1e-12);
  EXPECT_TRUE(earlier_checks(rows, "ffffffffffffffff", "2026-11-27").empty());
  EXPECT_EQ(last_check(rows, "00000000000000ab")->verdict, "noisier today");
  // Refused: a time that is not ISO 8601, a name with a line break.
  EXPECT_THROW(append_check_history(path, "yesterday", "x.csv", a_check(MonitorVerdict::kValid, 0)),
               FileError);
  EXPECT_THROW(append_check_history(path, "2026-11-26T10:00:00Z", "x\n.csv",
                                    a_check(MonitorVerdict::kValid, 0)),
               FileError);
  EXPECT_EQ(read_check_history(path).size(), 2u);
  fs::remove_all(dir);
}

TEST(CheckHistoryFile, TheFirstFormatIsReadAndKept) {
  const fs::path dir = fresh("first");
  const std::string path = (dir / "h.csv").string();
  std::ofstream(path) << "time,verdict,change_rms_mm,monitors,source\n"
                         "2026-11-26T08:00:00Z,valid,0.0100,3,a.csv\n";
  append_check_history(path, "2026-11-26T09:00:00Z", "b,c.csv",
                       a_check(MonitorVerdict::kRigidChange, 1e-4));
  const std::vector<CheckHistoryRow> rows = read_check_history(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].source, "b,c.csv");
  EXPECT_TRUE(rows[1].points.empty());
  EXPECT_EQ(rows[1].line, 3u);
  fs::remove_all(dir);
}

TEST(CheckHistoryFile, RowsAppendedAtOnceAreAllKeptWhole) {
  const fs::path dir = fresh("threads");
  const std::string path = (dir / "h.csv").string();
  constexpr int kThreads = 8, kRows = 25;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&path, t] {
      for (int k = 0; k < kRows; ++k)
        append_check_history(path, "2026-11-26T08:00:00Z", "t" + std::to_string(t) + ".csv",
                             a_check(MonitorVerdict::kValid, 1e-5 * (k + 1)));
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(read_check_history(path).size(), static_cast<std::size_t>(kThreads * kRows));
  fs::remove_all(dir);
}

TEST(CheckHistoryFile, OnlyARegularHistoryIsAppendedTo) {
  const fs::path dir = fresh("kinds");
  const std::string fifo = (dir / "fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(append_check_history(fifo, "2026-11-26T08:00:00Z", "a.csv",
                                    a_check(MonitorVerdict::kValid, 0)),
               FileError);  // refused, not blocked on
  EXPECT_THROW(append_check_history(dir.string(), "2026-11-26T08:00:00Z", "a.csv",
                                    a_check(MonitorVerdict::kValid, 0)),
               FileError);
  const std::string other = (dir / "other.csv").string();
  std::ofstream(other) << "point,role\nF1,fiducial\n";
  EXPECT_THROW(append_check_history(other, "2026-11-26T08:00:00Z", "a.csv",
                                    a_check(MonitorVerdict::kValid, 0)),
               FileError);
  std::ifstream in(other);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "point,role\nF1,fiducial\n");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::io::check_history_test
