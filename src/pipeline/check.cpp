// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "check_onset.hpp"
#include "monitor_visits.hpp"
#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/planning/spread_points.hpp"

namespace vrreg {
namespace {

// Below a nanometre the scatter is rounding, not a measurement.
constexpr double kLeastVariance = 1e-18;

// One visit's variance at one time: estimated (dof > 0), known (given: dof 0), or not at all.
struct VisitVariance {
  double m2 = 0.0;
  double dof = 0.0;
  bool known = false;
  [[nodiscard]] bool have() const { return known || dof > 0.0; }
};

VisitVariance estimated_variance(const pipeline_detail::VisitScatter& s) {
  if (s.dof <= 0.0 || !(s.sum_m2 / s.dof > kLeastVariance)) return {};
  return {s.sum_m2 / s.dof, s.dof, false};
}

// Satterthwaite's degrees of freedom of a u + b v (0: both known, the sum known).
double effective_dof(double a, const VisitVariance& u, double b, const VisitVariance& v) {
  const double x = a * u.m2, y = b * v.m2;
  double den = 0.0;
  if (!u.known) den += x * x / u.dof;
  if (!v.known) den += y * y / v.dof;
  return den == 0.0 ? 0.0 : (x + y) * (x + y) / den;
}

std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 0x100000001b3ULL;
  return h;
}

}  // namespace

void CheckOptions::validate() const {
  MonitorCheckOptions{false_alarm_rate, 0.0}.validate();
  VRREG_THROW_UNLESS(!visit_sd_m || (std::isfinite(*visit_sd_m) && *visit_sd_m > 0.0),
                     "`visit_sd` must be > 0");
  VRREG_THROW_UNLESS(earlier.empty() || (time_s && std::isfinite(*time_s)),
                     "earlier checks are told from today by time: give today's `time_s`");
  VRREG_THROW_UNLESS(remeasure >= 4,
                     "`remeasure` must be >= 4 (an affine drift has 12 "
                     "parameters), got "
                         << remeasure);
}

std::string location_key(const Location& location) {
  return location.config ? location.point + "@" + std::to_string(*location.config) : location.point;
}

std::string monitor_baseline_id(const RegistrationModel& model) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const auto add_double = [&h](double x) { h = fnv1a(h, &x, sizeof x); };
  for (const Location& m : model.monitors) {
    h = fnv1a(h, m.point.data(), m.point.size() + 1);
    const int config = m.config.value_or(-1), visit = m.visit.value_or(-1);
    h = fnv1a(h, &config, sizeof config);
    h = fnv1a(h, &visit, sizeof visit);
    for (int a = 0; a < 3; ++a) add_double(m.sensor_m(a));
  }
  if (model.T_registered_sensor) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) add_double(model.T_registered_sensor->rotation(r, c));
      add_double(model.T_registered_sensor->translation_m(r));
    }
  }
  const std::uint64_t updates = model.lineage.size();
  h = fnv1a(h, &updates, sizeof updates);
  return fmt::format("{:016x}", h);
}

CheckResult check_cell(const RegistrationModel& model, const MeasurementSet& today,
                       const CheckOptions& options) {
  options.validate();
  model.validate();
  CheckResult out;
  out.source = today.source;
  out.false_alarm_rate = options.false_alarm_rate;
  out.model_id = monitor_baseline_id(model);
  const pipeline_detail::MonitorPairs pairs = pipeline_detail::monitor_pairs(model, today);
  out.model_monitors = pairs.model_points;
  const auto n = static_cast<Eigen::Index>(pairs.points.size());

  // One visit's variance then and today, apart: a noisier day must not read as a change.
  VisitVariance then = estimated_variance(pairs.then), now = estimated_variance(pairs.today);
  if (options.visit_sd_m) then = {*options.visit_sd_m * *options.visit_sd_m, 0.0, true};
  if (!then.have() && !now.have()) {
    pipeline_detail::fail(today,
                          "the model's monitor points and today's were each read in one visit (or "
                          "their visits agree to within a nanometre): the sd of a visit cannot be "
                          "estimated; read them in several visits (a visit column) or give "
                          "`visit_sd`");
  }
  double rate = options.false_alarm_rate;
  bool shared = false;  // one estimate stands for both times
  if (then.have() && now.have()) {
    // Two tests share the stated rate (Sidak): today noisier, and the change.
    rate = -std::expm1(0.5 * std::log1p(-options.false_alarm_rate));
    out.noise = compare_visit_noise(then.m2, then.known ? 0.0 : then.dof, now.m2, now.dof, rate);
    // A given sd stands for today too unless today is significantly noisier.
    if (then.known && !out.noise.noisier) {
      now = then;
      shared = true;
    }
  } else if (!now.have()) {
    now = then;  // today read once: assumed as noisy as the registration (not tested)
    shared = true;
    out.noise = {then.m2, then.dof, then.m2, 0.0, 1.0, 1.0, false, false};
  } else {
    then = now;  // the registration's visits give no scatter: today's stands for both
    shared = true;
    out.noise = {now.m2, now.dof, now.m2, now.dof, 1.0, 1.0, false, false};
  }
  out.visit_sd_m = std::sqrt(then.m2);
  out.today_visit_sd_m = std::sqrt(now.m2);

  Points3 baseline(3, n), current(3, n);
  Eigen::VectorXd sd(n), baseline_mean_sd(n);
  double a_mean = 0.0, b_mean = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const pipeline_detail::MonitorPair& p = pairs.points[static_cast<std::size_t>(i)];
    baseline.col(i) = p.baseline_m;
    current.col(i) = p.today_m;
    const double a = 1.0 / p.baseline_visits, b = 1.0 / p.today_visits;
    a_mean += a / static_cast<double>(n);
    b_mean += b / static_cast<double>(n);
    sd(i) = std::sqrt(a * then.m2 + b * now.m2);
    baseline_mean_sd(i) = std::sqrt(a * then.m2);
    out.points.push_back({p.point, p.config, p.baseline_visits, p.today_visits,
                          p.today_m - p.baseline_m, sd(i), std::sqrt(b * now.m2)});
  }
  // The same estimate standing for both times: its own dof, exactly (F); apart: Satterthwaite.
  if (shared) {
    out.variance_dof = then.known ? 0.0 : then.dof;
  } else {
    // Rounded down: fewer dof, wider bounds; and repeated checks share split_rate's quadrature.
    const double dof = effective_dof(a_mean, then, b_mean, now);
    out.variance_dof = dof == 0.0 ? 0.0 : std::max(1.0, std::floor(dof));
  }
  MonitorCheckOptions check;
  check.false_alarm_rate = rate;
  check.variance_dof = out.variance_dof;
  out.statistics = check_monitors(baseline, current, sd, check);
  MonitorCheck& s = out.statistics;
  if (out.noise.noisier) {
    const std::string noisier = fmt::format(
        "today's visits scatter {:.2f} times the registration's variance (p = {:.2g}), and the "
        "test used today's own scatter",
        out.noise.ratio, out.noise.p_value);
    if (s.verdict == MonitorVerdict::kValid) {
      s.verdict = MonitorVerdict::kNoisier;
      s.message = "no change found, but " + noisier +
                  ": read the monitor points again when the cell is quieter, or in more visits (" +
                  s.message + ")";
    } else {
      s.message += "; " + noisier;
    }
  }
  if (s.verdict == MonitorVerdict::kRigidChange || s.verdict == MonitorVerdict::kSmoothChange)
    pipeline_detail::classify_onset(options, baseline_mean_sd, out);
  // A bump update needs 3 points off a line: with fewer monitors, fiducials to read with them.
  const bool few = s.verdict == MonitorVerdict::kRigidChange && s.rigid->rotation_rank < 3;
  if (s.verdict == MonitorVerdict::kSmoothChange || few) {
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
