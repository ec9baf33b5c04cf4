// SPDX-License-Identifier: Apache-2.0
#pragma once
// Field-level helpers for the measurement CSV: splitting, trimming, strict number parsing.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vrreg::io::detail {

/// `text` without leading and trailing spaces and tabs.
std::string_view trim(std::string_view text);

/// Splits `line` at every comma into trimmed fields (no quoting; see measurement_csv.hpp).
void split_fields(std::string_view line, std::vector<std::string_view>& fields);

/// A finite double from the whole of `text` (an optional leading '+'); nullopt otherwise.
std::optional<double> parse_finite_double(std::string_view text);

/// The largest |coordinate| a file may give [m]: 1 000 km. A robot cell spans metres; beyond this
/// a value is a typing or export error, and squared in a registration's sums (1e308) it
/// overflows. Millimetres written into a metre column (thousands of "metres") stay below it, so
/// that the plausibility warning can name the column.
inline constexpr double kMaxCoordinateM = 1e6;

/// Why coordinate `value_m` [m] is refused (out of range), or empty; `column` names it.
std::string coordinate_out_of_range(double value_m, std::string_view column, std::string_view text);

/// An int from the whole of `text` (an optional leading '+'); nullopt otherwise.
std::optional<int> parse_int(std::string_view text);

/// ASCII lower-case copy of `text`.
std::string to_lower(std::string_view text);

/// Shortest decimal text that reads back as exactly `value` (std::to_chars).
std::string format_double(double value);

}  // namespace vrreg::io::detail
