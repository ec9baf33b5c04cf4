// SPDX-License-Identifier: Apache-2.0
// A cell's check history on its report page: one trace per verdict, a noisier day drawn apart
// from a change (grey, not red), and every check that was not valid in the table.
#include "vrreg/report/monitor_history.hpp"

#include <gtest/gtest.h>

#include "report/charts.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg::report::monitor_history_test {
namespace {

io::CheckHistoryRow row(const std::string& time, const std::string& verdict, double mm) {
  io::CheckHistoryRow r;
  r.time = time;
  r.verdict = verdict;
  r.change_rms_mm = mm;
  r.monitors = 4;
  r.source = "a,b.csv";
  return r;
}

TEST(MonitorHistorySection, ANoisierDayIsNotDrawnAsAChange) {
  const ReportSection s =
      monitor_history_section({row("2026-11-26T08:00:00Z", "valid", 0.01),
                               row("2026-11-26T09:00:00Z", "noisier today", 0.02),
                               row("2026-11-26T10:00:00Z", "rigid change", 0.12)},
                              "h.csv");
  ASSERT_EQ(s.figures.size(), 1u);
  std::map<std::string, std::string> colour;
  for (const nlohmann::json& trace : s.figures[0].data)
    colour[trace["name"].get<std::string>()] = trace["marker"]["color"].get<std::string>();
  EXPECT_EQ(colour.at("noisier today"), charts::kNeutral);
  EXPECT_EQ(colour.at("rigid change"), charts::kFailed);
  ASSERT_EQ(s.tables.size(), 1u);
  ASSERT_EQ(s.tables[0].rows.size(), 2u);
  EXPECT_EQ(s.tables[0].rows[0][1], "noisier today");
  EXPECT_EQ(s.tables[0].rows[1][4], "a,b.csv");
  EXPECT_THROW(monitor_history_section({}, "h.csv"), InputError);
}

}  // namespace
}  // namespace vrreg::report::monitor_history_test
