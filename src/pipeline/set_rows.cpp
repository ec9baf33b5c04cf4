// SPDX-License-Identifier: Apache-2.0
#include "set_rows.hpp"

#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"

namespace vrreg::pipeline_detail {

void fail(const MeasurementSet& set, const std::string& message, std::size_t line) {
  if (set.source.empty()) throw InputError(message);
  throw FileError(set.source, line, message);
}

std::vector<std::size_t> select_rows(const MeasurementSet& set, Role role,
                                     std::optional<int> config) {
  std::vector<std::size_t> rows = set.select(role, config);
  const std::string what = to_string(role);
  if (config && !set.has_config) {
    fail(set, "`config` " + std::to_string(*config) + " given but the file has no config column");
  }
  if (rows.empty()) {
    fail(set, "no " + what + " rows" +
                  (config ? " with config " + std::to_string(*config) : std::string()));
  }
  return rows;
}

std::vector<std::size_t> source_lines(const MeasurementSet& set,
                                      const std::vector<std::size_t>& rows) {
  std::vector<std::size_t> lines;
  lines.reserve(rows.size());
  for (std::size_t i : rows) lines.push_back(set.locations[i].source_line);
  return lines;
}

void labels_of(const MeasurementSet& set, const std::vector<std::size_t>& rows,
               std::vector<std::string>& names, std::vector<std::optional<int>>& configs) {
  for (const std::size_t i : rows) {
    names.push_back(set.locations[i].point);
    configs.push_back(set.locations[i].config);
  }
}

std::vector<Location> locations_of(const MeasurementSet& set,
                                   const std::vector<std::size_t>& rows) {
  std::vector<Location> out;
  out.reserve(rows.size());
  for (std::size_t i : rows) out.push_back(set.locations[i]);
  return out;
}

Eigen::MatrixXd joints_of(const MeasurementSet& set, const std::vector<std::size_t>& rows) {
  const auto n_joints = static_cast<Eigen::Index>(set.n_joints);
  if (n_joints == 0) return {};
  Eigen::MatrixXd out(n_joints, static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::vector<double>& q = set.locations[rows[i]].q_rad;
    if (static_cast<Eigen::Index>(q.size()) != n_joints) return {};
    out.col(static_cast<Eigen::Index>(i)) = Eigen::Map<const Eigen::VectorXd>(q.data(), n_joints);
  }
  return out;
}

Eigen::MatrixXd approach_of(const MeasurementSet& set, const std::vector<std::size_t>& rows) {
  const auto n_joints = static_cast<Eigen::Index>(set.n_joints);
  if (n_joints == 0) return {};
  Eigen::MatrixXd out(n_joints, static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::vector<double>& s = set.locations[rows[i]].approach_sign;
    if (static_cast<Eigen::Index>(s.size()) != n_joints) return {};
    out.col(static_cast<Eigen::Index>(i)) = Eigen::Map<const Eigen::VectorXd>(s.data(), n_joints);
  }
  return out;
}

}  // namespace vrreg::pipeline_detail
