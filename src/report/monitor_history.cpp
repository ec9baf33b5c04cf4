// SPDX-License-Identifier: Apache-2.0
#include "vrreg/report/monitor_history.hpp"

#include <map>

#include "charts.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"

namespace vrreg::report {
namespace {

const char* colour_of(const std::string& verdict) {
  if (verdict == "valid") return charts::kCorrected;
  if (verdict == "outlier") return charts::kPaper;
  if (verdict == "noisier today") return charts::kNeutral;  // nothing found, the test was weaker
  return charts::kFailed;  // rigid or smooth change: the model no longer holds
}

}  // namespace

ReportSection monitor_history_section(const std::vector<io::CheckHistoryRow>& history,
                                      const std::string& history_name) {
  VRREG_THROW_UNLESS(!history.empty(), "the check history " << history_name << " has no checks");
  ReportSection s;
  s.heading = "Monitor history";
  int changed = 0;
  for (const io::CheckHistoryRow& r : history) changed += r.verdict == "valid" ? 0 : 1;
  s.paragraphs.push_back(
      std::to_string(history.size()) + " checks of the cell's monitor points (" + history_name +
      "), " + std::to_string(changed) +
      " of them not valid. A rigid change means the sensor moved (vrreg update --change bump), a "
      "smooth change that the robot drifted (read the fiducials the check names again, then "
      "vrreg update --change drift); noisier today that nothing was found but the readings "
      "scattered more than at registration (check again).");
  ReportFigure f;
  f.title = "Change at the monitor points per check";
  f.wide = true;
  std::map<std::string, std::vector<std::size_t>> by_verdict;
  for (std::size_t i = 0; i < history.size(); ++i) by_verdict[history[i].verdict].push_back(i);
  for (const auto& [verdict, rows] : by_verdict) {
    nlohmann::json x = nlohmann::json::array(), y = nlohmann::json::array(),
                   text = nlohmann::json::array();
    for (const std::size_t i : rows) {
      x.push_back(history[i].time);
      y.push_back(charts::round_to(history[i].change_rms_mm, 4));
      text.push_back(history[i].source);
    }
    f.data.push_back({{"type", "scatter"},
                      {"mode", "markers"},
                      {"name", verdict},
                      {"x", std::move(x)},
                      {"y", std::move(y)},
                      {"text", std::move(text)},
                      {"marker", {{"size", 9}, {"color", colour_of(verdict)}}}});
  }
  f.layout = charts::xy_layout("check time", "RMS change at the monitor points [mm]");
  f.caption =
      "One point per check; blue: valid, red: the sensor moved or the robot drifted, "
      "orange: one monitor point moved, grey: noisier today.";
  s.figures.push_back(std::move(f));
  ReportTable t;
  t.title = "Checks that were not valid";
  t.header = {"time", "verdict", "change mm", "monitor points", "file"};
  for (const io::CheckHistoryRow& r : history) {
    if (r.verdict == "valid") continue;
    t.rows.push_back({r.time, r.verdict, format_fixed(r.change_rms_mm, 4),
                      std::to_string(r.monitors), r.source});
  }
  if (!t.rows.empty()) s.tables.push_back(std::move(t));
  return s;
}

}  // namespace vrreg::report
