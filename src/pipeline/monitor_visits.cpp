// SPDX-License-Identifier: Apache-2.0
#include "monitor_visits.hpp"

#include <map>
#include <utility>

#include "set_rows.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg::pipeline_detail {
namespace {

using Key = std::pair<std::string, std::optional<int>>;

struct Visits {
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> means_m;
  std::size_t first_line = 0;
};

// Mean of the visits; adds their scatter about it to `scatter`.
Eigen::Vector3d mean_of(const Visits& v, VisitScatter& scatter) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& x : v.means_m) mean += x;
  mean /= static_cast<double>(v.means_m.size());
  for (const Eigen::Vector3d& x : v.means_m) scatter.sum_m2 += (x - mean).squaredNorm();
  scatter.dof += 3.0 * static_cast<double>(v.means_m.size() - 1);
  return mean;
}

}  // namespace

MonitorPairs monitor_pairs(const RegistrationModel& model, const MeasurementSet& today) {
  std::vector<Key> order;
  std::map<Key, Visits> then, now;
  for (const Location& m : model.monitors) {
    const Key key{m.point, m.config};
    auto [it, added] = then.try_emplace(key);
    if (added) order.push_back(key);
    it->second.robot_m = m.robot_m;
    it->second.means_m.push_back(m.sensor_m);
  }
  // About the model, not today's file: InputError, which the caller names the model by.
  VRREG_THROW_UNLESS(!then.empty(),
                     "the model has no monitor points: register with monitor rows (role monitor; "
                     "`vrreg plan --monitor` chooses them)");
  const std::vector<std::size_t> rows = today.select(Role::kMonitor);
  if (rows.empty()) fail(today, "no monitor rows (role monitor)");
  const Points3 sensor = model.registered_sensor_points(today.sensor_points(rows));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Location& m = today.locations[rows[k]];
    const Key key{m.point, m.config};
    if (!then.contains(key)) {
      fail(today,
           "monitor point '" + m.point + "'" +
               (m.config ? " config " + std::to_string(*m.config) : std::string()) +
               " is not one of the model's monitor points",
           m.source_line);
    }
    Visits& v = now[key];
    if (v.means_m.empty()) v.first_line = m.source_line;
    v.means_m.push_back(sensor.col(static_cast<Eigen::Index>(k)));
  }
  MonitorPairs out;
  out.model_points = static_cast<int>(order.size());
  for (const Key& key : order) {
    const auto it = now.find(key);
    if (it == now.end()) continue;
    MonitorPair p;
    p.point = key.first;
    p.config = key.second;
    const Visits& before = then.at(key);
    p.robot_m = before.robot_m;
    p.baseline_m = mean_of(before, out.then);
    p.today_m = mean_of(it->second, out.today);
    p.today_as_read_m = model.T_registered_sensor
                            ? model.T_registered_sensor->inverse().apply(p.today_m)
                            : p.today_m;
    p.baseline_visits = static_cast<int>(before.means_m.size());
    p.today_visits = static_cast<int>(it->second.means_m.size());
    out.points.push_back(std::move(p));
  }
  return out;
}

}  // namespace vrreg::pipeline_detail
