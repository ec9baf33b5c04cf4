// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `vrreg check` and `vrreg update` print with --json (lengths in mm), and a cell's check
// history: one CSV row per check (time, verdict, change, the model and each point's move),
// appended by `vrreg check --history` under a file lock, read back by the next check (how a change
// came: pipeline/check.hpp) and drawn by `vrreg report --history`.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vrreg/pipeline/check.hpp"
#include "vrreg/pipeline/update.hpp"

namespace vrreg::io {

/// check: verdict, its message, test statistics and bounds, the visit sds then and today and
/// their comparison, each monitor point's difference, the rigid change (mrad, mm; the translation
/// at the sensor's origin and at the points' centroid, each with its covariance), how the change
/// came (from the history), what the points cannot tell, the fiducials to read again.
nlohmann::json check_json(const CheckResult& result);
/// update: the change, the points used, the fit's RMS, the sensor move (bump) or the affine
/// drift (drift), today's monitors checked again, the lineage.
nlohmann::json update_json(const UpdateResult& result);

/// One monitor point of a history row.
struct CheckHistoryPoint {
  std::string point{};
  std::optional<int> config{};
  Eigen::Vector3d moved_mm = Eigen::Vector3d::Zero();  ///< today - then, registration frame
  double mean_sd_mm = 0.0;                             ///< sd of that check's mean per axis
};

/// One row of a check history.
struct CheckHistoryRow {
  std::string time{};     ///< ISO 8601, as given
  std::string verdict{};  ///< to_string(MonitorVerdict)
  double change_rms_mm = 0.0;
  int monitors = 0;                         ///< monitor points read
  std::string source{};                     ///< the file checked
  std::string model_id{};                   ///< monitor_baseline_id; empty in the first format
  std::vector<CheckHistoryPoint> points{};  ///< empty in the first format
  std::size_t line = 0;                     ///< where it is in the file
};

/// Appends one row for `result` checked at `time` (ISO 8601) from the file `source`: the file is
/// created with its header when absent or empty, locked (flock, exclusive) while it is read,
/// validated and appended to, and the row is written whole or, on a failed write, cut off again.
/// `source` is quoted as CSV quotes (a comma or a double quote in it). A history in the first
/// format (5 columns) gets rows of that format. Throws FileError on a file that is not a regular
/// file or not a history, a time that is not ISO 8601, or a file name with a line break.
void append_check_history(const std::string& path, const std::string& time,
                          const std::string& source, const CheckResult& result);
/// Reads a history (either format); throws FileError naming the line on a malformed row.
std::vector<CheckHistoryRow> read_check_history(const std::string& path);
/// The same from text (`path` for messages).
std::vector<CheckHistoryRow> parse_check_history(const std::string& text, const std::string& path);

/// The checks of the model with `model_id` strictly before `time` (ISO 8601), oldest first, as
/// check_cell takes them (CheckOptions::earlier); rows whose time is not ISO 8601, of another
/// model, or of the first format (no points) are left out.
std::vector<EarlierCheck> earlier_checks(const std::vector<CheckHistoryRow>& history,
                                         const std::string& model_id, const std::string& time);

/// The latest check of the model with `model_id` (by time; the last row among equal times).
std::optional<CheckHistoryRow> last_check(const std::vector<CheckHistoryRow>& history,
                                          const std::string& model_id);

/// The MonitorVerdict named `text` (to_string's words); throws InputError otherwise.
MonitorVerdict parse_verdict(const std::string& text);

/// The ISO 8601 forms --time takes, in words for help and errors.
inline constexpr const char* kIso8601Forms =
    "YYYY-MM-DD, YYYY-MM-DDThh:mm, YYYY-MM-DDThh:mm:ss or YYYY-MM-DDThh:mm:ss.fff, each time "
    "optionally followed by Z or an offset +hh:mm, +hhmm, +hh (or -); without one, UTC";

/// Seconds since 1970-01-01T00:00:00Z of an ISO 8601 date or date and time (kIso8601Forms; the
/// fields range-checked, leap years included); nullopt for anything else.
std::optional<double> parse_iso8601_s(std::string_view text);

/// The current UTC time as ISO 8601 ("2026-11-26T17:03:00Z").
std::string utc_now();

}  // namespace vrreg::io
