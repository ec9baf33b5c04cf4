// SPDX-License-Identifier: Apache-2.0
// A cell's check history: one CSV row per check, appended under an exclusive file lock so that
// checks run at once each add their whole row.
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <sstream>

#include "csv_fields.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/io/monitor_json.hpp"

namespace vrreg::io {
namespace {

// The first format (time to source) and the current one, which adds the model and each point.
constexpr std::string_view kHeaderFirst = "time,verdict,change_rms_mm,monitors,source";
constexpr std::string_view kHeader = "time,verdict,change_rms_mm,monitors,source,model_id,points";

// A field as CSV writes it: quoted (quotes doubled) when it holds a comma, a quote or leading or
// trailing spaces; line breaks are refused by the caller.
std::string csv_field(const std::string& text) {
  const bool plain = text.find_first_of(",\"") == std::string::npos &&
                     (text.empty() || (text.front() != ' ' && text.back() != ' '));
  if (plain) return text;
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// Splits a CSV line with quoted fields; unquoted fields are trimmed. nullopt: a quote unclosed or
// followed by anything but a comma.
std::optional<std::vector<std::string>> split_csv(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t at = 0;
  while (true) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    std::string field;
    if (at < line.size() && line[at] == '"') {
      ++at;
      bool closed = false;
      while (at < line.size()) {
        if (line[at] == '"') {
          if (at + 1 < line.size() && line[at + 1] == '"') {
            field += '"';
            at += 2;
            continue;
          }
          ++at;
          closed = true;
          break;
        }
        field += line[at++];
      }
      if (!closed) return std::nullopt;
      while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
      if (at < line.size() && line[at] != ',') return std::nullopt;
    } else {
      const std::size_t comma = std::min(line.find(',', at), line.size());
      field = std::string(detail::trim(line.substr(at, comma - at)));
      at = comma;
    }
    fields.push_back(std::move(field));
    if (at >= line.size()) break;
    ++at;  // the comma
  }
  return fields;
}

// Point names go into the points field percent-encoded beyond a safe set: no space, ';', '@'.
bool safe_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("-_.~+/:", c) != nullptr;
}

std::string encode_name(const std::string& name) {
  if (name.empty()) return "%";  // a lone percent: the empty name
  std::string out;
  for (const char c : name) {
    out += safe_char(c) ? std::string(1, c) : fmt::format("%{:02X}", static_cast<unsigned char>(c));
  }
  return out;
}

std::optional<std::string> decode_name(std::string_view text) {
  if (text == "%") return std::string();
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      out += text[i];
      continue;
    }
    if (i + 2 >= text.size() || !std::isxdigit(static_cast<unsigned char>(text[i + 1])) ||
        !std::isxdigit(static_cast<unsigned char>(text[i + 2])))
      return std::nullopt;
    out += static_cast<char>(std::stoi(std::string(text.substr(i + 1, 2)), nullptr, 16));
    i += 2;
  }
  if (out.empty()) return std::nullopt;  // no name at all
  return out;
}

// "name[@config] dx dy dz sd" per point (mm), joined by ';'.
std::string points_field(const CheckResult& r) {
  std::string out;
  for (const MonitorPointCheck& p : r.points) {
    if (!out.empty()) out += ';';
    out += encode_name(p.point);
    if (p.config) out += "@" + std::to_string(*p.config);
    const Eigen::Vector3d mm = units::m_to_mm(1.0) * p.difference_m;
    out += fmt::format(" {:.6f} {:.6f} {:.6f} {:.6f}", mm.x(), mm.y(), mm.z(),
                       units::m_to_mm(p.today_mean_sd_m));
  }
  return out;
}

std::vector<CheckHistoryPoint> parse_points(const std::string& field, const std::string& path,
                                            std::size_t line) {
  std::vector<CheckHistoryPoint> out;
  std::istringstream entries(field);
  std::string entry;
  while (std::getline(entries, entry, ';')) {
    if (detail::trim(entry).empty()) continue;
    std::istringstream words{std::string(detail::trim(entry))};
    std::string key;
    std::vector<std::string> numbers;
    words >> key;
    for (std::string w; words >> w;) numbers.push_back(w);
    CheckHistoryPoint p;
    const std::size_t at = key.find('@');
    const std::optional<std::string> name = decode_name(std::string_view(key).substr(0, at));
    if (at != std::string::npos) {
      const std::optional<int> config = detail::parse_int(std::string_view(key).substr(at + 1));
      if (!config) throw FileError(path, line, "points: '" + key + "' has a bad config label");
      p.config = *config;
    }
    if (!name || numbers.size() != 4)
      throw FileError(path, line,
                      "points: expected 'name[@config] dx dy dz sd' (mm), got '" + entry + "'");
    double v[4];
    for (int k = 0; k < 4; ++k) {
      const std::optional<double> x =
          detail::parse_finite_double(numbers[static_cast<std::size_t>(k)]);
      if (!x)
        throw FileError(path, line,
                        "points: '" + numbers[static_cast<std::size_t>(k)] + "' is not a number");
      v[k] = *x;
    }
    if (v[3] < 0.0) throw FileError(path, line, "points: a negative sd");
    p.point = *name;
    p.moved_mm = Eigen::Vector3d(v[0], v[1], v[2]);
    p.mean_sd_mm = v[3];
    out.push_back(std::move(p));
  }
  return out;
}

// The history's rows and which header it has (true: the current one).
struct ParsedHistory {
  std::vector<CheckHistoryRow> rows;
  bool current = true;
};

ParsedHistory parse_history(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  std::string line;
  ParsedHistory out;
  std::size_t number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    const std::string_view content = detail::trim(line);
    if (content.empty() || content.front() == '#') continue;
    if (!header) {
      if (content != kHeader && content != kHeaderFirst)
        throw FileError(path, number, "expected the header '" + std::string(kHeader) + "'");
      out.current = content == kHeader;
      header = true;
      continue;
    }
    const std::optional<std::vector<std::string>> fields = split_csv(content);
    const std::size_t expected = out.current ? 7 : 5;
    if (!fields) throw FileError(path, number, "a quoted field is not closed");
    if (fields->size() != expected)
      throw FileError(path, number, "expected " + std::to_string(expected) + " fields");
    const std::vector<std::string>& f = *fields;
    CheckHistoryRow row;
    row.line = number;
    row.time = f[0];
    row.verdict = f[1];
    const std::optional<double> change = detail::parse_finite_double(f[2]);
    const std::optional<int> monitors = detail::parse_int(f[3]);
    if (!change || *change < 0.0)
      throw FileError(path, number, "change_rms_mm is not a number >= 0");
    if (!monitors || *monitors < 1) throw FileError(path, number, "monitors is not a count >= 1");
    try {
      (void)parse_verdict(row.verdict);
    } catch (const InputError& e) {
      throw FileError(path, number, e.what());
    }
    row.change_rms_mm = *change;
    row.monitors = *monitors;
    row.source = f[4];
    if (out.current) {
      row.model_id = f[5];
      row.points = parse_points(f[6], path, number);
    }
    out.rows.push_back(std::move(row));
  }
  if (!header) throw FileError(path, 0, "empty history (no header line)");
  return out;
}

[[noreturn]] void fail_system(const std::string& path, const std::string& what) {
  throw FileError(path, 0, what + ": " + std::strerror(errno));
}

// Closes the descriptor (and so drops its lock) on every way out.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::string read_all(int fd, off_t size, const std::string& path) {
  std::string text(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t got =
        ::pread(fd, text.data() + done, text.size() - done, static_cast<off_t>(done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail_system(path, "cannot read");
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  text.resize(done);
  return text;
}

}  // namespace

MonitorVerdict parse_verdict(const std::string& text) {
  for (const MonitorVerdict v :
       {MonitorVerdict::kValid, MonitorVerdict::kRigidChange, MonitorVerdict::kOutlier,
        MonitorVerdict::kSmoothChange, MonitorVerdict::kNoisier}) {
    if (text == to_string(v)) return v;
  }
  throw InputError("unknown verdict '" + text + "'");
}

std::vector<CheckHistoryRow> parse_check_history(const std::string& text, const std::string& path) {
  return parse_history(text, path).rows;
}

std::vector<CheckHistoryRow> read_check_history(const std::string& path) {
  return parse_check_history(read_input_file(path), path);
}

void append_check_history(const std::string& path, const std::string& time,
                          const std::string& source, const CheckResult& result) {
  if (!parse_iso8601_s(time)) {
    throw FileError(path, 0,
                    "cannot record the time '" + time + "': not ISO 8601 (" + kIso8601Forms + ")");
  }
  if (source.find_first_of("\r\n") != std::string::npos)
    throw FileError(path, 0, "cannot record the file name '" + source + "': it holds a line break");
  // Non-blocking open: a FIFO at the path must not hang the check; refused just below.
  Descriptor d{::open(path.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC | O_NONBLOCK, 0666)};
  if (d.fd < 0) fail_system(path, "cannot open to append");
  struct stat st {};
  if (::fstat(d.fd, &st) != 0) fail_system(path, "cannot stat");
  if (!S_ISREG(st.st_mode)) throw FileError(path, 0, "not a regular file (a check history is one)");
  if (::fcntl(d.fd, F_SETFL, ::fcntl(d.fd, F_GETFL) & ~O_NONBLOCK) != 0)
    fail_system(path, "cannot set blocking mode");
  while (::flock(d.fd, LOCK_EX) != 0) {
    if (errno != EINTR) fail_system(path, "cannot lock");
  }
  // Under the lock: the file as the last writer left it.
  if (::fstat(d.fd, &st) != 0) fail_system(path, "cannot stat");
  const off_t size = st.st_size;
  const std::string text = read_all(d.fd, size, path);
  bool current = true;
  if (!detail::trim(text).empty()) current = parse_history(text, path).current;
  std::string row = csv_field(time) + "," + to_string(result.statistics.verdict) + "," +
                    fmt::format("{:.4f}", units::m_to_mm(result.statistics.change_rms_m)) + "," +
                    std::to_string(result.points.size()) + "," + csv_field(source);
  if (current) row += "," + result.model_id + "," + points_field(result);
  row += "\n";
  if (detail::trim(text).empty())
    row = std::string(kHeader) + "\n" + row;
  else if (text.back() != '\n')
    row = "\n" + row;
  std::size_t done = 0;
  while (done < row.size()) {
    const ssize_t put = ::write(d.fd, row.data() + done, row.size() - done);
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) {
      const int error = errno;
      const bool cut = ::ftruncate(d.fd, size) == 0;
      errno = error;
      fail_system(path, cut ? "cannot append (nothing written)"
                            : "cannot append, nor cut the part written off again");
    }
    done += static_cast<std::size_t>(put);
  }
  if (::fsync(d.fd) != 0) fail_system(path, "cannot flush");
}

std::vector<EarlierCheck> earlier_checks(const std::vector<CheckHistoryRow>& history,
                                         const std::string& model_id, const std::string& time) {
  const std::optional<double> now = parse_iso8601_s(time);
  if (!now) return {};
  std::vector<std::pair<double, const CheckHistoryRow*>> rows;
  for (const CheckHistoryRow& r : history) {
    const std::optional<double> t = parse_iso8601_s(r.time);
    if (r.model_id == model_id && !r.points.empty() && t && *t < *now) rows.emplace_back(*t, &r);
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<EarlierCheck> out;
  for (const auto& [t, r] : rows) {
    EarlierCheck e;
    e.time = r->time;
    e.time_s = t;
    const MonitorVerdict v = parse_verdict(r->verdict);
    e.changed = v != MonitorVerdict::kValid && v != MonitorVerdict::kNoisier;
    for (const CheckHistoryPoint& p : r->points) {
      MonitorPointCheck c;
      c.point = p.point;
      c.config = p.config;
      c.difference_m = units::mm_to_m(1.0) * p.moved_mm;
      c.today_mean_sd_m = units::mm_to_m(p.mean_sd_mm);
      e.points.push_back(std::move(c));
    }
    out.push_back(std::move(e));
  }
  return out;
}

std::optional<CheckHistoryRow> last_check(const std::vector<CheckHistoryRow>& history,
                                          const std::string& model_id) {
  std::optional<CheckHistoryRow> out;
  double latest = 0.0;
  for (const CheckHistoryRow& r : history) {
    const std::optional<double> t = parse_iso8601_s(r.time);
    if (r.model_id != model_id || !t) continue;
    if (!out || *t >= latest) {
      out = r;
      latest = *t;
    }
  }
  return out;
}

}  // namespace vrreg::io
