// SPDX-License-Identifier: Apache-2.0
#include "line_protocol.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/rotation.hpp"

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

// The orientation keywords, the form each gives, and the bound on each number: a rotation vector
// [rad] or angles [deg] beyond it are typing errors.
struct OrientationKeyword {
  std::string_view name;
  OrientationForm form;
  double max_abs;
};
constexpr OrientationKeyword kOrientationKeywords[] = {
    {"rotvec", OrientationForm::kRotationVector, 100.0},
    {"quat", OrientationForm::kQuaternion, 2.0},
    {"abc", OrientationForm::kKukaAbc, 720.0},
};

const OrientationKeyword* orientation_keyword(std::string_view field) {
  for (const OrientationKeyword& k : kOrientationKeywords) {
    if (equals_ignoring_case(field, k.name)) return &k;
  }
  return nullptr;
}

bool is_keyword(std::string_view field) {
  return equals_ignoring_case(field, "config") || equals_ignoring_case(field, "joints") ||
         equals_ignoring_case(field, "from") || equals_ignoring_case(field, "approach") ||
         equals_ignoring_case(field, "extrapolate") || orientation_keyword(field) != nullptr;
}

// The form the reply to a request takes: that of the first orientation keyword in it, also when
// the request cannot be read, so that the client reads as many numbers as it expects.
OrientationForm form_of(const std::vector<std::string_view>& fields) {
  for (const std::string_view f : fields) {
    if (const OrientationKeyword* k = orientation_keyword(f)) return k->form;
  }
  return OrientationForm::kNone;
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
  if (!field.empty() && field.front() == '+') {
    field.remove_prefix(1);
    // from_chars would read the sign of "+-767.2" as the number's: two signs are a typing error.
    if (!field.empty() && (field.front() == '-' || field.front() == '+')) return std::nullopt;
  }
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

// The angles [rad] after `joints` or `from` (`keyword`), up to the next keyword; `value` names one.
std::optional<std::string> read_angles(std::string_view keyword, std::string_view value,
                                       const std::vector<std::string_view>& fields, std::size_t& i,
                                       std::vector<double>& out) {
  while (i < fields.size() && !is_keyword(fields[i])) {
    const std::optional<double> q = number_of(fields[i]);
    if (!q || std::abs(*q) > 100.0) {
      return fmt::format("{} '{}' is not a finite angle in rad", value, shown(fields[i]));
    }
    if (out.size() == kMaxJoints) return std::string("more than 16 joints");
    out.push_back(*q);
    ++i;
  }
  if (out.empty()) return fmt::format("{} without values", keyword);
  return std::nullopt;
}

// The signs -1, 0, +1 after `approach`, up to the next keyword.
std::optional<std::string> read_signs(const std::vector<std::string_view>& fields, std::size_t& i,
                                      std::vector<double>& out) {
  while (i < fields.size() && !is_keyword(fields[i])) {
    const std::optional<double> s = number_of(fields[i]);
    if (!s || (*s != -1.0 && *s != 0.0 && *s != 1.0)) {
      return "approach sign '" + shown(fields[i]) + "' is not -1, 0 or 1";
    }
    if (out.size() == kMaxJoints) return std::string("approach: more than 16 joints");
    out.push_back(*s == 0.0 ? 0.0 : *s);  // no "-0"
    ++i;
  }
  if (out.empty()) return std::string("approach without values");
  return std::nullopt;
}

BadRequest malformed(std::string reason) { return {ReplyCode::kMalformed, std::move(reason)}; }

// The marker's orientation after its keyword, as a unit quaternion.
std::optional<Eigen::Quaterniond> orientation_of(const OrientationKeyword& k,
                                                 const std::vector<std::string_view>& fields,
                                                 std::size_t& i, std::string& why) {
  const int count = orientation_numbers(k.form);
  Eigen::Vector4d v = Eigen::Vector4d::Zero();
  for (int c = 0; c < count; ++c, ++i) {
    const std::optional<double> x =
        i < fields.size() ? number_of(fields[i]) : std::optional<double>();
    if (!x || std::abs(*x) > k.max_abs) {
      why = fmt::format("{} takes {} finite numbers (within {}){}", k.name, count, k.max_abs,
                        i < fields.size() ? ", not '" + shown(fields[i]) + "'" : std::string());
      return std::nullopt;
    }
    v(c) = *x;
  }
  switch (k.form) {
    case OrientationForm::kRotationVector:
      return Eigen::Quaterniond(rotation_exp(v.head<3>()));
    case OrientationForm::kKukaAbc:
      return Eigen::Quaterniond(rotation_from_kuka_abc_deg(v.head<3>()));
    case OrientationForm::kQuaternion:
      try {
        return unit_quaternion(v, "quat");
      } catch (const InputError& e) {
        why = e.what();
        return std::nullopt;
      }
    case OrientationForm::kNone:
      break;
  }
  return std::nullopt;
}

LineRequest parse_fields(const std::vector<std::string_view>& fields);

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
  LineRequest request = parse_fields(fields);
  if (auto* bad = std::get_if<BadRequest>(&request)) bad->form = form_of(fields);
  return request;
}

namespace {

LineRequest parse_fields(const std::vector<std::string_view>& fields) {
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
  bool seen_from = false;
  bool seen_approach = false;
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
      if (auto why = read_angles("joints", "joint", fields, i, request.joints_rad)) {
        return malformed(*why);
      }
    } else if (equals_ignoring_case(key, "from") && !seen_from && !seen_approach) {
      seen_from = true;
      if (auto why = read_angles("from", "from joint", fields, i, request.from_rad)) {
        return malformed(*why);
      }
    } else if (equals_ignoring_case(key, "approach") && !seen_approach && !seen_from) {
      seen_approach = true;
      if (auto why = read_signs(fields, i, request.approach_sign)) return malformed(*why);
    } else if (const OrientationKeyword* k = orientation_keyword(key);
               k != nullptr && request.orientation_form == OrientationForm::kNone) {
      std::string why;
      request.q_sensor_marker = orientation_of(*k, fields, i, why);
      if (!request.q_sensor_marker) return malformed(why);
      request.orientation_form = k->form;
    } else {
      return malformed("unexpected '" + shown(key) +
                       "' (after x y z: config <label>, joints <q_rad...>, from <q_rad...> or "
                       "approach <signs...>, extrapolate, and one of rotvec/quat/abc, once each)");
    }
  }
  if (seen_from) {
    if (!seen_joints) return malformed("from without joints (the approach is joints - from)");
    if (request.from_rad.size() != request.joints_rad.size()) {
      return malformed(fmt::format("from has {} joints, joints {}", request.from_rad.size(),
                                   request.joints_rad.size()));
    }
    request.approach_sign = approach_sign_of_move(request.from_rad, request.joints_rad);
  }
  if (seen_approach && seen_joints && request.approach_sign.size() != request.joints_rad.size()) {
    return malformed(fmt::format("approach has {} signs, joints {}", request.approach_sign.size(),
                                 request.joints_rad.size()));
  }
  return request;
}

}  // namespace

std::string format_reply_number(double value) {
  if (value == 0.0) value = 0.0;  // "-0" is no number a controller need know
  std::string s = format_general(value, 12);
  if (s.find('e') != std::string::npos) s = format_fixed(value, 15);
  return s;
}

Eigen::VectorXd orientation_in(const Eigen::Quaterniond& q, OrientationForm form) {
  switch (form) {
    case OrientationForm::kRotationVector:
      return rotation_log(q.toRotationMatrix());
    case OrientationForm::kKukaAbc:
      return kuka_abc_deg(q.toRotationMatrix());
    case OrientationForm::kQuaternion: {
      // The sign with w >= 0 (q and -q are the same orientation): one answer for one point.
      const Eigen::Quaterniond u = q.w() < 0.0 ? Eigen::Quaterniond(-q.coeffs()) : q;
      return u.coeffs();
    }
    case OrientationForm::kNone:
      break;
  }
  return {};
}

std::string format_line_reply(const PointAnswer& answer, OrientationForm form) {
  const int n_orientation = orientation_numbers(form);
  if (answer.code != ReplyCode::kOk) {
    std::string zeros = "0,0,0,";
    for (int k = 0; k < n_orientation; ++k) zeros += "0,";
    const int code = static_cast<int>(answer.code);
    return n_orientation == 0 ? fmt::format("({}-{})\n", zeros, code)
                              : fmt::format("({}-{},-{})\n", zeros, code, code);
  }
  std::string out = "(" + format_reply_number(answer.robot_mm.x()) + "," +
                    format_reply_number(answer.robot_mm.y()) + "," +
                    format_reply_number(answer.robot_mm.z()) + ",";
  if (n_orientation > 0) {
    const Eigen::VectorXd o = orientation_in(answer.q_robot_marker.value(), form);
    for (Eigen::Index k = 0; k < o.size(); ++k) out += format_reply_number(o(k)) + ",";
  }
  out += format_reply_number(answer.sd_mm);
  if (n_orientation > 0) out += "," + format_reply_number(1e3 * answer.angle_sd_rad);
  return out + ")\n";
}

std::string line_auth_accepted() { return "(1)\n"; }

}  // namespace vrreg::serve
