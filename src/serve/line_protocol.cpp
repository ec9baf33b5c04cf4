// SPDX-License-Identifier: Apache-2.0
#include "line_protocol.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include "vrreg/core/format.hpp"

namespace vrreg::serve {
namespace {

// Coordinates beyond 10^9 mm (1 000 km) are typing errors, not cells.
constexpr double kMaxAbsMm = 1e9;
constexpr std::size_t kMaxJoints = 16;
constexpr std::size_t kMaxModelName = 64;

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ','; }

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_separator(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_separator(line[i])) ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
           return lower(x) == lower(y);
         });
}

bool is_keyword(std::string_view field) {
  return equals_ignoring_case(field, "config") || equals_ignoring_case(field, "joints") ||
         equals_ignoring_case(field, "extrapolate");
}

bool valid_model_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxModelName) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '_' || c == '-' || c == '.';
  });
}

// A finite number within kMaxAbsMm; from_chars takes "nan" and "inf", the service does not.
std::optional<double> number_of(std::string_view field) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size() || !std::isfinite(value) ||
      std::abs(value) > kMaxAbsMm) {
    return std::nullopt;
  }
  return value;
}

std::string shown(std::string_view field) {
  std::string out;
  for (const char c : field.substr(0, 32)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  return field.size() > 32 ? out + "..." : out;
}

BadRequest malformed(std::string reason) { return {ReplyCode::kMalformed, std::move(reason)}; }

}  // namespace

LineRequest parse_line_request(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  for (const char c : line) {
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t') {
      return malformed("control character in the request");
    }
    if (static_cast<unsigned char>(c) >= 0x7f) return malformed("non-ASCII byte in the request");
  }
  const std::vector<std::string_view> fields = fields_of(line);
  if (fields.empty()) return malformed("empty request");
  if (equals_ignoring_case(fields[0], "auth")) {
    if (fields.size() != 2) return malformed("auth takes one token");
    return AuthRequest{std::string(fields[1])};
  }
  if (!valid_model_name(fields[0])) {
    return malformed("model name '" + shown(fields[0]) +
                     "': letters, digits, '_', '-', '.' (at most 64)");
  }
  if (fields.size() < 4) return malformed("expected <model> <x_mm> <y_mm> <z_mm>");
  PointRequest request;
  request.model = std::string(fields[0]);
  for (int a = 0; a < 3; ++a) {
    const std::optional<double> v = number_of(fields[static_cast<std::size_t>(a) + 1]);
    if (!v) {
      return malformed(fmt::format("{} coordinate '{}' is not a finite number of mm within 1e9",
                                   "xyz"[a], shown(fields[static_cast<std::size_t>(a) + 1])));
    }
    request.sensor_mm[a] = *v;
  }
  bool seen_config = false;
  bool seen_joints = false;
  for (std::size_t i = 4; i < fields.size();) {
    const std::string_view key = fields[i++];
    if (equals_ignoring_case(key, "extrapolate") && !request.extrapolate) {
      request.extrapolate = true;
    } else if (equals_ignoring_case(key, "config") && !seen_config) {
      seen_config = true;
      int label = 0;
      const std::string_view value = i < fields.size() ? fields[i++] : std::string_view();
      const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), label);
      if (value.empty() || error != std::errc() || end != value.data() + value.size()) {
        return malformed("config '" + shown(value) + "' is not an integer label");
      }
      request.config = label;
    } else if (equals_ignoring_case(key, "joints") && !seen_joints) {
      seen_joints = true;
      while (i < fields.size() && !is_keyword(fields[i])) {
        const std::optional<double> q = number_of(fields[i]);
        if (!q || std::abs(*q) > 100.0) {
          return malformed("joint '" + shown(fields[i]) + "' is not a finite angle in rad");
        }
        if (request.joints_rad.size() == kMaxJoints) return malformed("more than 16 joints");
        request.joints_rad.push_back(*q);
        ++i;
      }
      if (request.joints_rad.empty()) return malformed("joints without values");
    } else {
      return malformed("unexpected '" + shown(key) +
                       "' (after x y z: config <label>, joints <q_rad...>, extrapolate, once each)");
    }
  }
  return request;
}

std::string format_reply_mm(double value_mm) {
  std::string s = format_general(value_mm, 12);
  if (s.find('e') != std::string::npos) s = format_fixed(value_mm, 15);
  return s;
}

std::string format_line_reply(const PointAnswer& answer) {
  if (answer.code != ReplyCode::kOk) {
    return fmt::format("(0,0,0,-{})\n", static_cast<int>(answer.code));
  }
  return "(" + format_reply_mm(answer.robot_mm.x()) + "," + format_reply_mm(answer.robot_mm.y()) +
         "," + format_reply_mm(answer.robot_mm.z()) + "," + format_reply_mm(answer.sd_mm) + ")\n";
}

std::string line_auth_accepted() { return "(1)\n"; }

}  // namespace vrreg::serve
