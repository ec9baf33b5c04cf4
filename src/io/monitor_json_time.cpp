// SPDX-License-Identifier: Apache-2.0
// ISO 8601 times as `vrreg check --time` and the check history take them.
#include <fmt/chrono.h>

#include <cctype>
#include <ctime>

#include "vrreg/io/monitor_json.hpp"

namespace vrreg::io {
namespace {

// Days from 1970-01-01 to year-month-day (proleptic Gregorian; H. Hinnant's days_from_civil).
long long days_from_civil(long long y, unsigned m, unsigned d) {
  y -= m <= 2 ? 1 : 0;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

bool leap(long long y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

// Reads exactly `digits` decimal digits at `at`; advances it.
std::optional<int> digits_at(std::string_view text, std::size_t& at, int digits) {
  if (at + static_cast<std::size_t>(digits) > text.size()) return std::nullopt;
  int value = 0;
  for (int k = 0; k < digits; ++k) {
    const char c = text[at + static_cast<std::size_t>(k)];
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    value = 10 * value + (c - '0');
  }
  at += static_cast<std::size_t>(digits);
  return value;
}

bool skip_char(std::string_view text, std::size_t& at, char c) {
  if (at < text.size() && text[at] == c) {
    ++at;
    return true;
  }
  return false;
}

}  // namespace

std::optional<double> parse_iso8601_s(std::string_view text) {
  std::size_t at = 0;
  const auto year = digits_at(text, at, 4);
  if (!year || !skip_char(text, at, '-')) return std::nullopt;
  const auto month = digits_at(text, at, 2);
  if (!month || !skip_char(text, at, '-')) return std::nullopt;
  const auto day = digits_at(text, at, 2);
  if (!day || *month < 1 || *month > 12 || *day < 1) return std::nullopt;
  constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const int days = kDays[*month - 1] + (*month == 2 && leap(*year) ? 1 : 0);
  if (*day > days) return std::nullopt;
  double seconds =
      86400.0 * static_cast<double>(days_from_civil(*year, static_cast<unsigned>(*month),
                                                    static_cast<unsigned>(*day)));
  if (at == text.size()) return seconds;
  if (!skip_char(text, at, 'T')) return std::nullopt;
  const auto hour = digits_at(text, at, 2);
  if (!hour || *hour > 23 || !skip_char(text, at, ':')) return std::nullopt;
  const auto minute = digits_at(text, at, 2);
  if (!minute || *minute > 59) return std::nullopt;
  seconds += 3600.0 * *hour + 60.0 * *minute;
  if (skip_char(text, at, ':')) {
    const auto second = digits_at(text, at, 2);
    if (!second || *second > 60) return std::nullopt;  // 60: a leap second
    seconds += *second;
    if (skip_char(text, at, '.')) {
      double scale = 0.1;
      const std::size_t first = at;
      while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) {
        seconds += scale * (text[at] - '0');
        scale *= 0.1;
        ++at;
      }
      if (at == first) return std::nullopt;
    }
  }
  if (at == text.size() || skip_char(text, at, 'Z'))
    return at == text.size() ? std::optional(seconds) : std::nullopt;
  const char sign = text[at];
  if (sign != '+' && sign != '-') return std::nullopt;
  ++at;
  const auto offset_h = digits_at(text, at, 2);
  if (!offset_h || *offset_h > 23) return std::nullopt;
  int offset_min = 0;
  if (at < text.size()) {
    skip_char(text, at, ':');
    const auto m = digits_at(text, at, 2);
    if (!m || *m > 59) return std::nullopt;
    offset_min = *m;
  }
  if (at != text.size()) return std::nullopt;
  // Local time = UTC + offset.
  const double offset_s = 3600.0 * *offset_h + 60.0 * offset_min;
  return sign == '+' ? seconds - offset_s : seconds + offset_s;
}

std::string utc_now() {
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::time(nullptr)));
}

}  // namespace vrreg::io
