// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/rrbc_run.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/improvement.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg/metrics/rigid_body.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg::experiments {

RrbcRunFigures run_rrbc(const MeasurementSet& set, const std::vector<std::size_t>& fiducials,
                        const std::vector<std::size_t>& targets, const RrbcRunOptions& options) {
  const Points3 fid_sensor = set.sensor_points(fiducials);
  const Points3 fid_robot = set.robot_points(fiducials);
  const Points3 tgt_sensor = set.sensor_points(targets);
  const Points3 tgt_robot = set.robot_points(targets);

  const RegistrationResult reg = register_rigid(fid_sensor, fid_robot);
  CorrectionField field;  // no visiting order: corners measured once (datasets A1, A2, KUKA)
  field.T_robot_sensor = reg.T_robot_sensor;
  field.fiducials_robot_m = fid_robot;
  field.corrections_sensor_m = fiducial_corrections(reg.T_robot_sensor, fid_sensor, fid_robot);
  std::vector<Location> fiducial_locations;
  for (std::size_t i : fiducials) fiducial_locations.push_back(set.locations[i]);

  RrbcRunFigures f;
  f.n_fiducials = static_cast<int>(fiducials.size());
  f.n_targets = static_cast<int>(targets.size());
  if (options.rigid_body_statistics) {
    const RigidBodyStatistics stats = rigid_body_statistics(fid_sensor, fid_robot);
    f.sigma_l_m = stats.sigma_l_m;
    if (options.l_histogram_bin_m > 0.0) {
      f.l_histogram = l_histogram(fid_sensor, fid_robot, options.l_histogram_bin_m, stats);
    }
  }
  const NoiseFigures noise = noise_figures(
      options.sigma_opt_m ? options.sigma_opt_m : sigma_opt_m(fiducial_locations),
      options.sigma_rep_m, f.sigma_l_m);  // Eq. 9
  f.sigma_opt_m = noise.sigma_opt_m.value_or(0.0);
  f.sigma_noise_m = noise.sigma_noise_m.value_or(0.0);
  f.rho = noise.rho.value_or(0.0);

  const TargetCorrection c = correct_targets(field, tgt_sensor, tgt_robot, options.interpolation);
  const Eigen::VectorXd unc = point_errors(c.uncorrected_robot_m, tgt_robot);
  const Eigen::VectorXd cor = point_errors(c.corrected_robot_m, tgt_robot);
  const ImprovementSummary s = summarize_improvement(unc, cor);
  f.unc_rms_t_m = s.unc_rms_t_m;
  f.cor_rms_t_m = s.cor_rms_t_m;
  f.gamma = s.gamma;
  f.n_bad = s.n_bad;
  f.n_flagged = c.n_flagged;
  f.unc_tre_m = unc;
  f.cor_tre_m = cor;
  return f;
}

Histogram l_histogram(const ConstPoints3Ref& sensor_m, const ConstPoints3Ref& robot_m, double bin_m,
                      const RigidBodyStatistics& range) {
  VRREG_THROW_UNLESS(std::isfinite(bin_m) && bin_m > 0.0,
                     "L histogram: bin width must be > 0, got " << bin_m << " m");
  const double lo = std::floor(range.min_m / bin_m);
  const double hi = std::floor(range.max_m / bin_m) + 1.0;
  VRREG_THROW_UNLESS(hi - lo <= 1e6,
                     "L histogram: " << hi - lo << " bins of " << bin_m << " m are too many");
  return rigid_body_histogram(sensor_m, robot_m, static_cast<int>(hi - lo), lo * bin_m, hi * bin_m);
}

}  // namespace vrreg::experiments
