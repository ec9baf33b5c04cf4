// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/monitor_json.hpp"

#include <fmt/chrono.h>

#include <ctime>
#include <filesystem>
#include <sstream>

#include "csv_fields.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/io/result_json.hpp"

namespace vrreg::io {
namespace {

constexpr const char* kHistoryHeader = "time,verdict,change_rms_mm,monitors,source";

nlohmann::json optional_config(const std::optional<int>& config) {
  return config ? nlohmann::json(*config) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json check_json(const CheckResult& r) {
  const MonitorCheck& s = r.statistics;
  nlohmann::json j;
  j["verdict"] = to_string(s.verdict);
  j["message"] = s.message;
  j["false_alarm_rate"] = r.false_alarm_rate;
  j["n_monitors"] = r.points.size();
  j["model_monitors"] = r.model_monitors;
  j["visit_sd_mm"] = units::m_to_mm(r.visit_sd_m);
  j["visit_sd_dof"] = r.variance_dof;
  j["change_rms_mm"] = units::m_to_mm(s.change_rms_m);
  j["chi2"] = s.chi2;
  j["dof"] = s.dof;
  if (s.rigid_threshold > 0.0) {
    j["rigid_chi2"] = s.rigid_chi2;
    j["rigid_bound"] = s.rigid_threshold;
    j["residual_chi2"] = s.rigid_residual_chi2;
    j["residual_bound"] = s.residual_threshold;
  } else {
    j["bound"] = s.threshold;
  }
  nlohmann::json points = nlohmann::json::array();
  for (const MonitorPointCheck& p : r.points) {
    points.push_back({{"point", p.point},
                      {"config", optional_config(p.config)},
                      {"baseline_visits", p.baseline_visits},
                      {"today_visits", p.today_visits},
                      {"moved_mm", json_mm3(p.difference_m)},
                      {"sd_mm", units::m_to_mm(p.difference_sd_m)}});
  }
  j["points"] = std::move(points);
  if (s.rigid) {
    const RigidChange& c = *s.rigid;
    nlohmann::json cov = nlohmann::json::array();
    for (int i = 0; i < 6; ++i) {
      nlohmann::json row = nlohmann::json::array();
      // (omega [mrad], t [mm]): both scale by 1e3 from (rad, m).
      for (int k = 0; k < 6; ++k) row.push_back(1e6 * c.covariance(i, k));
      cov.push_back(std::move(row));
    }
    j["sensor_moved"] = {
        {"rotation_mrad",
         {1e3 * c.rotation_rad.x(), 1e3 * c.rotation_rad.y(), 1e3 * c.rotation_rad.z()}},
        {"translation_mm", json_mm3(c.translation_m)},
        {"covariance_mrad_mm", std::move(cov)},
        {"displacement_rms_mm", units::m_to_mm(c.displacement_rms_m)}};
  }
  if (s.outlier) j["outlier"] = r.points[static_cast<std::size_t>(*s.outlier)].point;
  j["remeasure"] = r.remeasure;
  j["source"] = r.source;
  return j;
}

nlohmann::json update_json(const UpdateResult& r) {
  nlohmann::json j;
  const ModelUpdate& last = r.model.lineage.back();
  j["change"] = last.change;
  j["points"] = r.points;
  j["n_monitors"] = r.n_monitors;
  j["n_fiducials"] = r.n_fiducials;
  j["fit_rms_mm"] = units::m_to_mm(r.fit_rms_m);
  if (last.change == "bump") {
    nlohmann::json rotation = nlohmann::json::array();
    for (int i = 0; i < 3; ++i) {
      rotation.push_back({r.T_registered_sensor.rotation(i, 0),
                          r.T_registered_sensor.rotation(i, 1),
                          r.T_registered_sensor.rotation(i, 2)});
    }
    j["T_registered_sensor"] = {{"rotation", std::move(rotation)},
                                {"translation_mm", json_mm3(r.T_registered_sensor.translation_m)}};
  } else {
    nlohmann::json a = nlohmann::json::array();
    for (int i = 0; i < 3; ++i) a.push_back({r.drift(i, 0), r.drift(i, 1), r.drift(i, 2)});
    j["drift"] = {{"per_metre", std::move(a)}, {"offset_mm", json_mm3(r.drift.col(3))}};
  }
  nlohmann::json lineage = nlohmann::json::array();
  for (const ModelUpdate& u : r.model.lineage) {
    lineage.push_back({{"change", u.change},
                       {"parent", u.parent},
                       {"points_source", u.points_source},
                       {"n_points", u.points.size()},
                       {"time", u.time},
                       {"fit_rms_mm", units::m_to_mm(u.fit_rms_m)}});
  }
  j["lineage"] = std::move(lineage);
  return j;
}

std::vector<CheckHistoryRow> read_check_history(const std::string& path) {
  const std::string text = read_input_file(path);
  std::istringstream in(text);
  std::string line;
  std::vector<CheckHistoryRow> rows;
  std::vector<std::string_view> fields;
  std::size_t number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    const std::string_view content = detail::trim(line);
    if (content.empty() || content.front() == '#') continue;
    if (!header) {
      if (content != kHistoryHeader)
        throw FileError(path, number, std::string("expected the header '") + kHistoryHeader + "'");
      header = true;
      continue;
    }
    detail::split_fields(line, fields);
    if (fields.size() != 5) throw FileError(path, number, "expected 5 fields");
    CheckHistoryRow row;
    row.time = fields[0];
    row.verdict = fields[1];
    const std::optional<double> change = detail::parse_finite_double(fields[2]);
    const std::optional<int> monitors = detail::parse_int(fields[3]);
    if (!change || *change < 0.0)
      throw FileError(path, number, "change_rms_mm is not a number >= 0");
    if (!monitors || *monitors < 1) throw FileError(path, number, "monitors is not a count >= 1");
    if (row.verdict != "valid" && row.verdict != "rigid change" && row.verdict != "outlier" &&
        row.verdict != "smooth change") {
      throw FileError(path, number, "unknown verdict '" + row.verdict + "'");
    }
    row.change_rms_mm = *change;
    row.monitors = *monitors;
    row.source = fields[4];
    rows.push_back(std::move(row));
  }
  if (!header) throw FileError(path, 0, "empty history (no header line)");
  return rows;
}

void append_check_history(const std::string& path, const std::string& time,
                          const std::string& source, const CheckResult& result) {
  std::string text;
  if (std::filesystem::exists(path)) {
    read_check_history(path);  // refuse to append to something that is not a history
    text = read_input_file(path);
    if (!text.empty() && text.back() != '\n') text += '\n';
  } else {
    text = std::string(kHistoryHeader) + "\n";
  }
  for (const std::string& field : {time, source}) {
    if (field.find_first_of(",\n\r") != std::string::npos)
      throw FileError(path, 0, "cannot record '" + field + "': it holds a comma or a line break");
  }
  text += time + "," + to_string(result.statistics.verdict) + "," +
          fmt::format("{:.4f}", units::m_to_mm(result.statistics.change_rms_m)) + "," +
          std::to_string(result.points.size()) + "," + source + "\n";
  write_file_atomically(path, text);
}

std::string utc_now() {
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::time(nullptr)));
}

}  // namespace vrreg::io
