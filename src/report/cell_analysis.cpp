// SPDX-License-Identifier: Apache-2.0
// The numbers behind a cell report (Eq. 1, 3, 4, 9; section 5.1's gamma, N_bad, Delta TRE).
#include <algorithm>
#include <cmath>

#include "charts.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg/report/cell_report.hpp"

namespace vrreg::report {
namespace {

// Procedure 2 in words, for the summary table; empty without a strategy.
std::string method_in_words(const EvaluateResult& e, const RegistrationModel& model) {
  const int s = planning::strategy_number(e.strategy);
  if (s == 0) return "";
  return "Strategy " + std::to_string(s) +
         (s > 1 ? std::string(" (") + kinematics::to_string(model.procedure2.joint_norm) +
                      " joint distance)"
                : std::string());
}

}  // namespace

CellAnalysis analyze_cell(const CellReportInput& input) {
  const RegistrationModel& model = input.model;
  const EvaluateResult& e = input.evaluation;
  CellAnalysis a;
  a.n_fiducials = static_cast<int>(model.fiducials.size());
  if (a.n_fiducials >= 2) {
    Points3 sensor(3, a.n_fiducials);
    Points3 robot(3, a.n_fiducials);
    for (int j = 0; j < a.n_fiducials; ++j) {
      sensor.col(j) = model.fiducials[static_cast<std::size_t>(j)].sensor_m;
      robot.col(j) = model.fiducials[static_cast<std::size_t>(j)].robot_m;
    }
    const SigmaLOptions sampling;  // as register: all pairs up to 20 000 fiducials, else sampled
    const RigidBodyEstimate estimate = rigid_body_estimate(sensor, robot, sampling);
    a.rigid_body = estimate.statistics;
    a.sigma_l_sampling = estimate.sampling;
    // About 60 bins of a round width over the bulk of L (mean +- 5 sigma_L, within min..max).
    const double s = std::max(a.rigid_body.sigma_l_m, 1e-9);
    const double lo = std::max(a.rigid_body.min_m, a.rigid_body.mean_m - 5 * s);
    const double hi = std::min(a.rigid_body.max_m, a.rigid_body.mean_m + 5 * s);
    const Eigen::Vector2d range(lo, hi > lo ? hi : lo + 1e-6);
    const Histogram shape = charts::auto_histogram(range, 60);
    const int bins = static_cast<int>(shape.counts.size());
    const double hi_m = shape.lo_m + shape.bin_width_m * static_cast<double>(bins);
    a.l_histogram = a.sigma_l_sampling.sampled
                        ? rigid_body_histogram_sampled(sensor, robot, bins, shape.lo_m, hi_m,
                                                       a.sigma_l_sampling.pairs_sampled,
                                                       a.sigma_l_sampling.seed)
                        : rigid_body_histogram(sensor, robot, bins, shape.lo_m, hi_m);
  }
  a.noise = noise_figures(sigma_opt_m(model.fiducials),
                          input.sigma_rep_m ? input.sigma_rep_m : model.sigma_rep_m,
                          a.rigid_body.sigma_l_m);
  a.method = method_in_words(e, model);
  a.targets_robot_m = e.targets_robot_m;
  for (std::size_t k = 0; k < e.names.size(); ++k) {
    const std::optional<int>& config = e.configs[k];
    a.labels.push_back(config && !e.config
                           ? e.names[k] + " (config " + std::to_string(*config) + ")"
                           : e.names[k]);
    a.configs.push_back(config);
  }
  a.unc_tre_m = e.unc_tre_m;
  a.cor_tre_m = e.cor_tre_m;
  a.summary = e.summary;
  a.where_bad = describe_locations(a.targets_robot_m, a.summary.bad_targets);
  return a;
}

}  // namespace vrreg::report
