// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reads measurement CSV files (design.md 6) into a MeasurementSet in SI units.
//
// Format: a header line, then one row per reading. Required columns: point, role,
// robot_{x,y,z}_mm, sensor_{x,y,z}_mm (or _m, the same for all six); optional: config (integer),
// q1_rad..qN_rad (or _deg, one unit, contiguous from 1), repeat (integer). Columns in any order;
// names are case-insensitive. Role is `fiducial` or `target` (case-insensitive; no abbreviations).
// Lines starting with `#` are comments; blank lines (or lines of empty fields) are skipped; CRLF,
// a UTF-8 BOM and a missing final newline are accepted. Fields are plain text between commas,
// trimmed of spaces and tabs; double-quoted fields are rejected (labels cannot hold commas).
// Unknown columns are errors. Rows with the same (point, config) are repeat readings of one
// location and are averaged (running mean and sums of squared deviations), so memory grows with
// the number of locations, not the file size. Any bad input throws FileError naming file and line.
#include <cstddef>
#include <istream>
#include <string>

#include "vrreg/core/measurement.hpp"

namespace vrreg::io {

/// Options for reading a measurement CSV.
struct CsvReadOptions {
  bool require_robot = true;                 ///< false: robot columns may be absent (sensor only)
  std::size_t max_line_bytes = 1024 * 1024;  ///< longer lines are an error (binary or wrong file)
  double robot_tolerance_m = 1e-9;           ///< same point: robot positions must agree to this
  double joint_tolerance_rad = 1e-9;         ///< same (point, config): joints must agree to this
};

/// Reads the measurement CSV at `path`; throws FileError ("path:line: message") on bad input.
MeasurementSet read_measurement_csv(const std::string& path, const CsvReadOptions& options = {});

/// Reads a measurement CSV from a stream; `source_name` names it in errors and in the result.
MeasurementSet parse_measurement_csv(std::istream& in, const std::string& source_name,
                                     const CsvReadOptions& options = {});

}  // namespace vrreg::io
