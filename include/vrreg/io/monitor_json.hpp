// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `vrreg check` and `vrreg update` print with --json (lengths in mm), and a cell's check
// history: one CSV row per check (time, verdict, change), appended by `vrreg check --history`
// and drawn by `vrreg report --history`.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vrreg/pipeline/check.hpp"
#include "vrreg/pipeline/update.hpp"

namespace vrreg::io {

/// check: verdict, its message, test statistics and bounds, the visit sd, each monitor point's
/// difference, the rigid change (mrad, mm) when fitted, the fiducials to read again.
nlohmann::json check_json(const CheckResult& result);
/// update: the change, the points used, the fit's RMS, the sensor move (bump) or the affine
/// drift (drift), the lineage.
nlohmann::json update_json(const UpdateResult& result);

/// One row of a check history.
struct CheckHistoryRow {
  std::string time{};     ///< ISO 8601, as given
  std::string verdict{};  ///< to_string(MonitorVerdict)
  double change_rms_mm = 0.0;
  int monitors = 0;      ///< monitor points read
  std::string source{};  ///< the file checked
};

/// Appends one row for `result` (creating the file with its header); the file is rewritten whole
/// (never half-written). Throws FileError on an unreadable or malformed existing history.
void append_check_history(const std::string& path, const std::string& time,
                          const std::string& source, const CheckResult& result);
/// Reads a history; throws FileError naming the line on a malformed row.
std::vector<CheckHistoryRow> read_check_history(const std::string& path);

/// The current UTC time as ISO 8601 ("2026-11-26T17:03:00Z").
std::string utc_now();

}  // namespace vrreg::io
