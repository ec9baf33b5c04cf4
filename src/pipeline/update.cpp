// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/update.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <map>
#include <utility>

#include "monitor_visits.hpp"
#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/pipeline/check.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg {
namespace {

// Corresponding readings: today's (registration frame for a drift, today's for a bump) and the
// registration's, with the robot position and a weight (1 / variance in units of one visit's).
struct Pairs {
  Points3 today_m;
  Points3 then_m;
  Points3 robot_m;
  Eigen::VectorXd weights;
  std::vector<std::string> names;
  int n_monitors = 0;
  int n_fiducials = 0;
};

Pairs pairs_of(const RegistrationModel& model, const MeasurementSet& today, bool today_frame) {
  std::vector<Eigen::Vector3d> now, then, robot;
  std::vector<double> weights;
  Pairs out;
  if (!today.select(Role::kMonitor).empty()) {
    const pipeline_detail::MonitorPairs m = pipeline_detail::monitor_pairs(model, today);
    for (const pipeline_detail::MonitorPair& p : m.points) {
      now.push_back(today_frame ? p.today_as_read_m : p.today_m);
      then.push_back(p.baseline_m);
      robot.push_back(p.robot_m);
      weights.push_back(1.0 / (1.0 / p.baseline_visits + 1.0 / p.today_visits));
      out.names.push_back(p.config ? p.point + "@" + std::to_string(*p.config) : p.point);
      ++out.n_monitors;
    }
  }
  std::map<std::pair<std::string, std::optional<int>>, std::size_t> fiducial_index;
  for (std::size_t j = 0; j < model.fiducials.size(); ++j)
    fiducial_index.emplace(std::make_pair(model.fiducials[j].point, model.fiducials[j].config), j);
  for (const std::size_t i : today.select(Role::kFiducial)) {
    const Location& f = today.locations[i];
    const auto it = fiducial_index.find({f.point, f.config});
    if (it == fiducial_index.end()) {
      pipeline_detail::fail(today, "fiducial '" + location_key(f) + "' is not one of the model's",
                            f.source_line);
    }
    const Location& before = model.fiducials[it->second];
    now.push_back(today_frame || !model.T_registered_sensor
                      ? f.sensor_m
                      : model.T_registered_sensor->apply(f.sensor_m));
    then.push_back(before.sensor_m);
    robot.push_back(before.robot_m);
    weights.push_back(0.5);  // one visit then, one today
    out.names.push_back(location_key(f));
    ++out.n_fiducials;
  }
  const auto n = static_cast<Eigen::Index>(now.size());
  out.today_m.resize(3, n);
  out.then_m.resize(3, n);
  out.robot_m.resize(3, n);
  out.weights.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto s = static_cast<std::size_t>(k);
    out.today_m.col(k) = now[s];
    out.then_m.col(k) = then[s];
    out.robot_m.col(k) = robot[s];
    out.weights(k) = weights[s];
  }
  return out;
}

ModelUpdate lineage_entry(const UpdateOptions& options, const MeasurementSet& today,
                          const Pairs& pairs, double fit_rms_m) {
  return {to_string(options.change),
          options.parent,
          today.source,
          pairs.names,
          options.time,
          fit_rms_m};
}

UpdateResult bump(const RegistrationModel& model, const MeasurementSet& today,
                  const UpdateOptions& options) {
  const Pairs pairs = pairs_of(model, today, true);
  if (pairs.today_m.cols() < 3) {
    pipeline_detail::fail(today,
                          "a bump update needs 3 or more points read today (monitor or "
                          "fiducial rows the model knows), got " +
                              std::to_string(pairs.today_m.cols()));
  }
  RegistrationResult fit;
  try {
    fit = register_rigid(pairs.today_m, pairs.then_m, {}, pairs.weights);  // Eq. 2
  } catch (const InputError& e) {
    pipeline_detail::fail(today,
                          std::string("the points cannot fix the sensor's move: ") + e.what());
  }
  UpdateResult out;
  out.model = model;
  out.T_registered_sensor = fit.T_robot_sensor.rigid();
  out.model.T_registered_sensor = out.T_registered_sensor;
  out.points = pairs.names;
  out.n_monitors = pairs.n_monitors;
  out.n_fiducials = pairs.n_fiducials;
  out.fit_rms_m = fit.fre_m;
  out.model.lineage.push_back(lineage_entry(options, today, pairs, out.fit_rms_m));
  return out;
}

UpdateResult drift(const RegistrationModel& model, const MeasurementSet& today,
                   const UpdateOptions& options) {
  VRREG_THROW_UNLESS(model.procedure2.strategy == planning::Strategy::kNone && !model.marker_offset,
                     "a drift update registers the model's fiducials again: not available for "
                     "models built with a Procedure 2 strategy or a marker offset; register "
                     "again");
  const Pairs pairs = pairs_of(model, today, false);
  const Eigen::Index n = pairs.today_m.cols();
  if (n < 4) {
    pipeline_detail::fail(today,
                          "a drift update needs 4 or more points read today (monitor or "
                          "fiducial rows the model knows), got " +
                              std::to_string(n));
  }
  // Weighted least squares of d = A p + b, p about its weighted centroid for conditioning.
  const Eigen::VectorXd sw = pairs.weights.cwiseSqrt();
  const Eigen::Vector3d centre = (pairs.robot_m * pairs.weights) / pairs.weights.sum();
  Eigen::MatrixXd design(n, 4);
  design.leftCols<3>() = (pairs.robot_m.colwise() - centre).transpose();
  design.col(3).setOnes();
  design = sw.asDiagonal() * design;
  const Eigen::MatrixXd rhs = sw.asDiagonal() * (pairs.today_m - pairs.then_m).transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(design, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::Vector4d s = svd.singularValues();
  if (s(3) <= 1e-6 * s(0)) {
    pipeline_detail::fail(today,
                          "the points read today are coplanar (or fewer than 4 distinct): "
                          "a drift across the volume cannot be fitted; read fiducials off "
                          "their plane");
  }
  const Eigen::Matrix<double, 4, 3> x = svd.solve(rhs);
  const Eigen::Matrix3d A = x.topRows<3>().transpose();
  const Eigen::Vector3d b = x.row(3).transpose() - A * centre;
  UpdateResult out;
  out.drift.leftCols<3>() = A;
  out.drift.col(3) = b;
  const auto change = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d { return A * p + b; };
  double ss = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Vector3d r =
        pairs.today_m.col(k) - pairs.then_m.col(k) - change(pairs.robot_m.col(k));
    ss += pairs.weights(k) * r.squaredNorm();
  }
  out.fit_rms_m = std::sqrt(ss / pairs.weights.sum());

  // Every fiducial and monitor reading moved by the fitted change, then registered again.
  MeasurementSet moved;
  moved.source = model.source;
  for (Location f : model.fiducials) {
    f.sensor_m += change(f.robot_m);
    moved.locations.push_back(std::move(f));
  }
  for (Location m : model.monitors) {
    m.sensor_m += change(m.robot_m);
    moved.locations.push_back(std::move(m));
  }
  moved.n_joints = model.fiducials.front().q_rad.empty()
                       ? 0
                       : static_cast<int>(model.fiducials.front().q_rad.size());
  moved.has_config = model.config.has_value();
  RegisterOptions again;
  again.config = model.config;
  again.sigma_rep_m = model.sigma_rep_m;
  again.robot = model.robot;
  again.interpolation = model.interpolation;
  again.rigid_body_statistics = model.sigma_l_m > 0.0;
  out.model = register_fiducials(moved, again).model;
  out.model.source = model.source;
  out.model.T_registered_sensor = model.T_registered_sensor;
  out.model.lineage = model.lineage;
  out.points = pairs.names;
  out.n_monitors = pairs.n_monitors;
  out.n_fiducials = pairs.n_fiducials;
  out.model.lineage.push_back(lineage_entry(options, today, pairs, out.fit_rms_m));
  return out;
}

// An update on a day the check found nothing fits noise into the model.
void refuse_if_unchanged(const MeasurementSet& today, const std::optional<CheckResult>& check,
                         const std::optional<MonitorVerdict>& last_verdict) {
  const auto unchanged = [](MonitorVerdict v) {
    return v == MonitorVerdict::kValid || v == MonitorVerdict::kNoisier;
  };
  const std::string anyway =
      ": an update would fit noise into the model; give `even_if_unchanged` "
      "(vrreg update --even-if-unchanged) to update anyway";
  if (check && unchanged(check->statistics.verdict)) {
    pipeline_detail::fail(today, "today's monitor readings show no change (" +
                                     std::string(to_string(check->statistics.verdict)) + ": " +
                                     check->statistics.message + ")" + anyway);
  }
  if (!check && last_verdict && unchanged(*last_verdict)) {
    pipeline_detail::fail(today, "the last check of this model found no change (" +
                                     std::string(to_string(*last_verdict)) + ")" + anyway);
  }
}

}  // namespace

const char* to_string(CellChange change) { return change == CellChange::kBump ? "bump" : "drift"; }

UpdateResult update_model(const RegistrationModel& model, const MeasurementSet& today,
                          const UpdateOptions& options) {
  model.validate();
  std::optional<CheckResult> check;
  if (!today.select(Role::kMonitor).empty() && !model.monitors.empty()) {
    try {
      check = check_cell(model, today, options.check);
    } catch (const InputError&) {
      // Not checkable (e.g. one visit each, then and today): the history's verdict decides, and
      // a file the update cannot use either fails below with its own message.
    }
  }
  if (!options.even_if_unchanged) refuse_if_unchanged(today, check, options.last_verdict);
  UpdateResult out = options.change == CellChange::kBump ? bump(model, today, options)
                                                         : drift(model, today, options);
  out.today_check = std::move(check);
  return out;
}

}  // namespace vrreg
