// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/distance_sweep.hpp"

#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/experiments/table1.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/improvement.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"

namespace vrreg::experiments {
namespace {

// Histogram of non-positive values in bins of `bin` whose edges are multiples of `bin`, from the
// bin holding the smallest value up to 0 (one empty bin when there are no values).
Histogram negative_histogram(const Eigen::VectorXd& values, double bin) {
  const double lo = values.size() > 0 ? std::floor(values.minCoeff() / bin) : -1.0;
  const double bins = std::max(1.0, -lo);
  return histogram(values, static_cast<int>(bins), lo * bin, (lo + bins) * bin);
}

}  // namespace

std::vector<double> dataset_b_cube_edges_m() {
  std::vector<double> edges;
  for (int mm = 50; mm >= 5; mm -= 5) edges.push_back(1e-3 * mm);
  return edges;
}

void DistanceSweepOptions::validate() const {
  VRREG_THROW_UNLESS(!cube_edges_m.empty(), "distance sweep: no cube edges");
  for (const double a : cube_edges_m) {
    VRREG_THROW_UNLESS(std::isfinite(a) && a > 4.0 * match_tolerance_m,
                       "distance sweep: cube edge " << a << " m is not > 4 x the tolerance");
  }
  VRREG_THROW_UNLESS(std::isfinite(match_tolerance_m) && match_tolerance_m > 0.0,
                     "distance sweep: the match tolerance must be > 0, got " << match_tolerance_m);
  VRREG_THROW_UNLESS(std::isfinite(delta_tre_bin_m) && delta_tre_bin_m > 0.0,
                     "distance sweep: the Delta TRE bin must be > 0, got " << delta_tre_bin_m);
}

const SweepStep& DistanceSweep::at_d_max() const {
  VRREG_THROW_UNLESS(!steps.empty(), "distance sweep: no steps");
  return *std::max_element(steps.begin(), steps.end(),
                           [](const SweepStep& a, const SweepStep& b) { return a.d_m < b.d_m; });
}

const SweepStep& DistanceSweep::at_d_min() const {
  VRREG_THROW_UNLESS(!steps.empty(), "distance sweep: no steps");
  return *std::min_element(steps.begin(), steps.end(),
                           [](const SweepStep& a, const SweepStep& b) { return a.d_m < b.d_m; });
}

DistanceSweep run_distance_sweep(const MeasurementSet& set, const DistanceSweepOptions& options) {
  options.validate();
  const std::vector<std::size_t> fid = set.select(Role::kFiducial);
  DistanceSweep out;
  const std::vector<std::size_t> tgt = set.select(Role::kTarget);
  VRREG_THROW_UNLESS(!tgt.empty(), "distance sweep: " << set.source << " has no targets");
  VRREG_THROW_UNLESS(fid.size() >= 3, "distance sweep: " << set.source << " has " << fid.size()
                                                         << " fiducials, needs at least 3");
  out.n_fiducials = static_cast<int>(fid.size());
  // One registration of every fiducial (the front door, as `vrreg register` does), then octuplet
  // corrections of every target with each cube edge (as `vrreg evaluate --cube-mm A` does).
  RegisterOptions registration;
  registration.rigid_body_statistics = false;
  registration.interpolation.match_tolerance_m = options.match_tolerance_m;
  const RegistrationModel model = register_fiducials(set, registration).model;

  const Points3 tgt_sensor = set.sensor_points(tgt);
  const Points3 tgt_robot = set.robot_points(tgt);
  out.target_robot_m = tgt_robot;
  for (const std::size_t i : tgt) out.target_points.push_back(set.locations[i].point);
  out.unc_tre_m = point_errors(model.T_robot_sensor.apply_all(tgt_sensor), tgt_robot);
  out.unc_rms_t_m = root_mean_square(out.unc_tre_m);

  Eigen::VectorXd delta_at_d_min;
  double d_min = 0.0;
  for (const double a : options.cube_edges_m) {
    EvaluateOptions octuplet;
    octuplet.interpolation.method = InterpolationMethod::kOctuplet;
    octuplet.interpolation.cube_edge_m = a;
    const TargetCorrection c = evaluate(model, set, octuplet).correction;
    SweepStep step;
    step.cube_edge_m = a;
    step.d_m = octuplet_distance_m(a);
    step.cor_tre_m = point_errors(c.corrected_robot_m, tgt_robot);
    const ImprovementSummary s = summarize_improvement(out.unc_tre_m, step.cor_tre_m);
    step.cor_rms_t_m = s.cor_rms_t_m;
    step.gamma = s.gamma;
    step.n_bad = s.n_bad;
    step.bad_targets = s.bad_targets;
    step.n_flagged = c.n_flagged;
    if (out.steps.empty() || step.d_m < d_min) {
      d_min = step.d_m;
      delta_at_d_min = s.delta_tre_m;
    }
    out.steps.push_back(std::move(step));
  }
  out.delta_tre_at_d_min_m = delta_at_d_min;
  out.delta_tre_histogram = negative_histogram(delta_at_d_min, options.delta_tre_bin_m);
  return out;
}

}  // namespace vrreg::experiments
