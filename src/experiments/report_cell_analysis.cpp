// The numbers behind a cell report (Eq. 1, 3, 4, 9; section 5.1's gamma, N_bad, Delta TRE).
#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/experiments/report_cell.hpp"
#include "vrreg/experiments/report_charts.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/noise.hpp"

namespace vrreg::experiments {

CellAnalysis analyze_cell(const CellReportInput& input) {
  const RegistrationModel& model = input.model;
  const TargetCorrection& c = input.correction;
  VRREG_THROW_UNLESS(c.corrected_robot_m.cols() == static_cast<Eigen::Index>(input.rows.size()),
                     "cell report: " << input.rows.size() << " target rows but "
                                     << c.corrected_robot_m.cols() << " corrected targets");
  CellAnalysis a;
  a.n_fiducials = static_cast<int>(model.fiducials.size());
  if (a.n_fiducials >= 2) {
    Points3 sensor(3, a.n_fiducials);
    Points3 robot(3, a.n_fiducials);
    for (int j = 0; j < a.n_fiducials; ++j) {
      sensor.col(j) = model.fiducials[static_cast<std::size_t>(j)].sensor_m;
      robot.col(j) = model.fiducials[static_cast<std::size_t>(j)].robot_m;
    }
    a.rigid_body = rigid_body_statistics(sensor, robot);
    // About 60 bins of a round width over the bulk of L (mean +- 5 sigma_L, within min..max).
    const double s = std::max(a.rigid_body.sigma_l_m, 1e-9);
    const double lo = std::max(a.rigid_body.min_m, a.rigid_body.mean_m - 5 * s);
    const double hi = std::min(a.rigid_body.max_m, a.rigid_body.mean_m + 5 * s);
    const Eigen::Vector2d range(lo, hi > lo ? hi : lo + 1e-6);
    const Histogram shape = charts::auto_histogram(range, 60);
    a.l_histogram = rigid_body_histogram(
        sensor, robot, static_cast<int>(shape.counts.size()), shape.lo_m,
        shape.lo_m + shape.bin_width_m * static_cast<double>(shape.counts.size()));
  }
  a.sigma_opt_m = sigma_opt_m(model.fiducials);
  if (a.sigma_opt_m || input.sigma_rep_m) {
    a.sigma_noise_m = sigma_noise_m(a.sigma_opt_m.value_or(0.0), input.sigma_rep_m.value_or(0.0));
    if (*a.sigma_noise_m > 0.0) a.rho = rho(a.rigid_body.sigma_l_m, *a.sigma_noise_m);
  }
  const Points3 targets_robot = input.targets.robot_points(input.rows);
  a.targets_robot_m = targets_robot;
  for (std::size_t k : input.rows) {
    const Location& loc = input.targets.locations[k];
    a.labels.push_back(loc.config && !input.config
                           ? loc.point + " (config " + std::to_string(*loc.config) + ")"
                           : loc.point);
    a.configs.push_back(loc.config);
  }
  a.unc_tre_m = point_errors(c.uncorrected_robot_m, targets_robot);
  a.cor_tre_m = point_errors(c.corrected_robot_m, targets_robot);
  a.summary = summarize_improvement(a.unc_tre_m, a.cor_tre_m);
  a.where_bad = describe_locations(targets_robot, a.summary.bad_targets);
  return a;
}

}  // namespace vrreg::experiments
