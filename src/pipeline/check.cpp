// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/check.hpp"

#include <cmath>

#include "monitor_visits.hpp"
#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/planning/spread_points.hpp"

namespace vrreg {

void CheckOptions::validate() const {
  MonitorCheckOptions{false_alarm_rate, 0.0}.validate();
  VRREG_THROW_UNLESS(!visit_sd_m || (std::isfinite(*visit_sd_m) && *visit_sd_m > 0.0),
                     "`visit_sd` must be > 0");
  VRREG_THROW_UNLESS(remeasure >= 4,
                     "`remeasure` must be >= 4 (an affine drift has 12 "
                     "parameters), got "
                         << remeasure);
}

std::string location_key(const Location& location) {
  return location.config ? location.point + "@" + std::to_string(*location.config) : location.point;
}

CheckResult check_cell(const RegistrationModel& model, const MeasurementSet& today,
                       const CheckOptions& options) {
  options.validate();
  model.validate();
  CheckResult out;
  out.source = today.source;
  out.false_alarm_rate = options.false_alarm_rate;
  const pipeline_detail::MonitorPairs pairs = pipeline_detail::monitor_pairs(model, today);
  out.model_monitors = pairs.model_points;
  const auto n = static_cast<Eigen::Index>(pairs.points.size());
  double visit_variance = 0.0;
  if (options.visit_sd_m) {
    visit_variance = *options.visit_sd_m * *options.visit_sd_m;
  } else {
    if (pairs.scatter_dof <= 0.0) {
      pipeline_detail::fail(today,
                            "each monitor point was read in one visit, then and today: the sd of "
                            "a visit cannot be estimated; read them in several visits (a visit "
                            "column) or give `visit_sd`");
    }
    visit_variance = pairs.scatter_m2 / pairs.scatter_dof;
    // Below a nanometre the scatter is rounding, not a measurement.
    if (!(visit_variance > 1e-18)) {
      pipeline_detail::fail(today,
                            "the monitor points' visits agree to within a nanometre: the "
                            "sd of a visit cannot be estimated; give `visit_sd`");
    }
    out.variance_dof = pairs.scatter_dof;
  }
  out.visit_sd_m = std::sqrt(visit_variance);
  Points3 then(3, n), now(3, n);
  Eigen::VectorXd sd(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const pipeline_detail::MonitorPair& p = pairs.points[static_cast<std::size_t>(i)];
    then.col(i) = p.baseline_m;
    now.col(i) = p.today_m;
    sd(i) = out.visit_sd_m * std::sqrt(1.0 / p.baseline_visits + 1.0 / p.today_visits);
    out.points.push_back(
        {p.point, p.config, p.baseline_visits, p.today_visits, p.today_m - p.baseline_m, sd(i)});
  }
  MonitorCheckOptions check;
  check.false_alarm_rate = options.false_alarm_rate;
  check.variance_dof = out.variance_dof;
  out.statistics = check_monitors(then, now, sd, check);
  if (out.statistics.verdict == MonitorVerdict::kSmoothChange) {
    Points3 fiducials(3, static_cast<Eigen::Index>(model.fiducials.size()));
    for (std::size_t j = 0; j < model.fiducials.size(); ++j)
      fiducials.col(static_cast<Eigen::Index>(j)) = model.fiducials[j].robot_m;
    for (const std::size_t j :
         planning::spread_points(fiducials, static_cast<std::size_t>(options.remeasure))) {
      out.remeasure.push_back(location_key(model.fiducials[j]));
    }
  }
  return out;
}

}  // namespace vrreg
