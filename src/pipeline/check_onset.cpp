// SPDX-License-Identifier: Apache-2.0
#include "check_onset.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace vrreg::pipeline_detail {
namespace {

// The earlier check's readings of today's points (sd 0 where it did not read one).
MonitorReadings readings_of(const EarlierCheck& earlier,
                            const std::vector<MonitorPointCheck>& today) {
  const auto n = static_cast<Eigen::Index>(today.size());
  MonitorReadings r{Points3::Zero(3, n), Eigen::VectorXd::Zero(n), earlier.time_s, earlier.changed};
  for (Eigen::Index i = 0; i < n; ++i) {
    const MonitorPointCheck& t = today[static_cast<std::size_t>(i)];
    for (const MonitorPointCheck& p : earlier.points) {
      if (p.point != t.point || p.config != t.config) continue;
      if (p.difference_m.allFinite() && std::isfinite(p.today_mean_sd_m) &&
          p.today_mean_sd_m > 0.0) {
        r.difference_m.col(i) = p.difference_m;
        r.mean_sd_m(i) = p.today_mean_sd_m;
      }
      break;
    }
  }
  return r;
}

std::string fractions_text(const std::vector<double>& fractions) {
  std::string text;
  for (const double f : fractions) text += fmt::format("{}{:.2f}", text.empty() ? "" : ", ", f);
  return text;
}

}  // namespace

void classify_onset(const CheckOptions& options, const Eigen::VectorXd& baseline_mean_sd_m,
                    CheckResult& out) {
  // Those before today that read any of today's points, in time order.
  std::vector<const EarlierCheck*> before;
  for (const EarlierCheck& e : options.earlier)
    if (std::isfinite(e.time_s) && e.time_s < *options.time_s) before.push_back(&e);
  std::stable_sort(before.begin(), before.end(), [](const EarlierCheck* a, const EarlierCheck* b) {
    return a->time_s < b->time_s;
  });
  std::vector<MonitorReadings> earlier;
  std::vector<std::string> times;
  for (const EarlierCheck* e : before) {
    MonitorReadings r = readings_of(*e, out.points);
    if (!(r.mean_sd_m.array() > 0.0).any()) continue;
    earlier.push_back(std::move(r));
    times.push_back(e->time);
  }
  if (earlier.size() > static_cast<std::size_t>(kMaxEarlierChecks)) {
    const auto drop = static_cast<std::ptrdiff_t>(earlier.size()) - kMaxEarlierChecks;
    earlier.erase(earlier.begin(), earlier.begin() + drop);
    times.erase(times.begin(), times.begin() + drop);
  }
  MonitorReadings today{Points3(3, static_cast<Eigen::Index>(out.points.size())),
                        Eigen::VectorXd(static_cast<Eigen::Index>(out.points.size())),
                        options.time_s.value_or(0.0), true};
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    today.difference_m.col(static_cast<Eigen::Index>(i)) = out.points[i].difference_m;
    today.mean_sd_m(static_cast<Eigen::Index>(i)) = out.points[i].today_mean_sd_m;
  }
  out.onset = classify_change_onset(baseline_mean_sd_m, earlier, today, options.false_alarm_rate);
  out.onset_times = times;
  MonitorCheck& s = out.statistics;
  if (out.onset.onset == ChangeOnset::kUnknown) {
    if (!options.earlier.empty()) s.message += "; " + out.onset.message;
    return;
  }
  const ChangeOnsetTest& o = out.onset;
  const std::string test =
      fmt::format("likelihood ratio of a linear ramp over a step {:.2f} {} {:.2f}", o.statistic,
                  o.onset == ChangeOnset::kRamp ? ">" : "<=", o.bound);
  if (o.onset == ChangeOnset::kStep) {
    const int j = o.step_after;
    const std::string from = j < 0 ? "the registration" : times[static_cast<std::size_t>(j)];
    const std::string to =
        j + 1 < o.earlier_checks ? times[static_cast<std::size_t>(j + 1)] : std::string("today");
    s.message += "; it came at once, between " + from + " and " + to + " (" + test + ")";
    return;
  }
  const std::string grew =
      "grew over the " + std::to_string(o.earlier_checks) +
      " earlier checks (their fractions of today's change: " + fractions_text(o.fractions) + "; " +
      test + ")";
  if (s.verdict == MonitorVerdict::kRigidChange) {
    // Rigid at the monitor points so far, but not at once: the robot is drifting (a warm-up).
    s.verdict = MonitorVerdict::kSmoothChange;
    s.rigid.reset();
    s.message = "changed, and the change " + grew +
                ": the robot drifting (a warm-up?), though rigid at the monitor points so far (" +
                s.message + ")";
    return;
  }
  s.message += "; it " + grew;
}

}  // namespace vrreg::pipeline_detail
