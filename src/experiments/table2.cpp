// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/table2.hpp"

#include <cmath>
#include <set>

#include "vrreg/core/check.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/improvement.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"

namespace vrreg::experiments {
namespace {

RrbcRunOptions per_label_options(const Table2Options& o) {
  RrbcRunOptions run;
  run.interpolation.method = InterpolationMethod::kOctuplet;
  run.interpolation.cube_edge_m = o.cube_edge_m;
  run.interpolation.match_tolerance_m = o.match_tolerance_m;
  run.sigma_rep_m = o.sigma_rep_m;
  run.sigma_opt_m = o.sigma_opt_m;
  run.l_histogram_bin_m = o.l_histogram_bin_m;
  return run;
}

void describe_targets(const MeasurementSet& set, const std::vector<std::size_t>& rows,
                      Table2Entry& e) {
  for (const std::size_t i : rows) e.target_points.push_back(set.locations[i].point);
  e.target_robot_m = set.robot_points(rows);
}

// Strategies 1 and 2: one registration per label of `set` (section 4.4).
Table2Entry per_label(const MeasurementSet& set, int config, int strategy,
                      const RrbcRunOptions& run) {
  Table2Entry e;
  e.config = config;
  e.strategy = strategy;
  const std::vector<std::size_t> targets = set.select(Role::kTarget, config);
  describe_targets(set, targets, e);
  e.figures = run_rrbc(set, set.select(Role::kFiducial, config), targets, run);
  return e;
}

// Strategy 3: the targets measured in `config`, corrected against the one registration.
Table2Entry strategy3(const MeasurementSet& set, int config, const RegistrationModel& model,
                      const Table2Options& o, double sigma_noise) {
  Table2Entry e;
  e.config = config;
  e.strategy = 3;
  const std::vector<std::size_t> rows = set.select(Role::kTarget, config);
  describe_targets(set, rows, e);
  EvaluateOptions targets_of_config;
  targets_of_config.config = config;
  targets_of_config.joint_norm = o.norm;
  const TargetCorrection c = evaluate(model, set, targets_of_config).correction;
  const std::size_t n_targets = rows.size();
  const Points3& robot = e.target_robot_m;
  RrbcRunFigures& f = e.figures;
  f.n_fiducials = 8;
  f.n_targets = static_cast<int>(n_targets);
  f.sigma_opt_m = o.sigma_opt_m;
  f.sigma_noise_m = sigma_noise;
  f.unc_tre_m = point_errors(c.uncorrected_robot_m, robot);
  f.cor_tre_m = point_errors(c.corrected_robot_m, robot);
  const ImprovementSummary s = summarize_improvement(f.unc_tre_m, f.cor_tre_m);
  f.unc_rms_t_m = s.unc_rms_t_m;
  f.cor_rms_t_m = s.cor_rms_t_m;
  f.gamma = s.gamma;
  f.n_bad = s.n_bad;
  f.n_flagged = c.n_flagged;
  return e;
}

}  // namespace

void Table2Options::validate() const {
  VRREG_THROW_UNLESS(std::isfinite(cube_edge_m) && cube_edge_m > 4.0 * match_tolerance_m,
                     "Table 2: the octuplet cube edge must be > 0, got " << cube_edge_m << " m");
  VRREG_THROW_UNLESS(std::isfinite(match_tolerance_m) && match_tolerance_m > 0.0,
                     "Table 2: the match tolerance must be > 0, got " << match_tolerance_m);
  VRREG_THROW_UNLESS(std::isfinite(sigma_opt_m) && sigma_opt_m >= 0.0 &&
                         std::isfinite(sigma_rep_m) && sigma_rep_m >= 0.0 &&
                         sigma_opt_m + sigma_rep_m > 0.0,
                     "Table 2: sigma_opt and sigma_rep must be >= 0 and not both 0, got "
                         << sigma_opt_m << " and " << sigma_rep_m << " m");
  VRREG_THROW_UNLESS(std::isfinite(l_histogram_bin_m) && l_histogram_bin_m >= 0.0,
                     "Table 2: the L histogram bin must be >= 0, got " << l_histogram_bin_m);
}

const Table2Entry& Table2::at(int config, int strategy) const {
  for (const Table2Entry& e : entries) {
    if (e.config == config && e.strategy == strategy) return e;
  }
  VRREG_THROW_UNLESS(false, "Table 2 has no configuration " << config << ", strategy " << strategy);
  return entries.front();  // not reached
}

bool Table2::switched(int config) const {
  const auto it = strategy2.switched_by_file_label.find(config);
  return it != strategy2.switched_by_file_label.end() && it->second > 0;
}

Table2 run_table2(const MeasurementSet& set, const Table2Options& options) {
  options.validate();
  VRREG_THROW_UNLESS(set.has_config, "Table 2: " << set.source << " has no config column");
  Table2 out;
  std::set<int> labels;
  for (const Location& loc : set.locations) {
    VRREG_THROW_UNLESS(loc.config, "Table 2: " << set.source << ": '" << loc.point
                                               << "' has no configuration label");
    labels.insert(*loc.config);
  }
  out.configs.assign(labels.begin(), labels.end());
  out.sigma_noise_m = sigma_noise_m(options.sigma_opt_m, options.sigma_rep_m);
  const planning::Strategy2Result ordered = planning::relabel_strategy2(set, options.norm);
  out.strategy2 = ordered.summary;

  // Strategy 3's one registration: the volume corners, each in a random configuration (the front
  // door, as `vrreg register --strategy 3 --seed N --cube-mm A` does).
  RegisterOptions s3;
  s3.rigid_body_statistics = false;
  s3.procedure2.strategy = planning::Strategy::kVolumeCorners;
  s3.procedure2.joint_norm = options.norm;
  s3.procedure2.seed = options.strategy3_seed;
  s3.interpolation.method = InterpolationMethod::kOctuplet;
  s3.interpolation.cube_edge_m = options.cube_edge_m;
  s3.interpolation.match_tolerance_m = options.match_tolerance_m;
  const RegistrationModel model = register_fiducials(set, s3).model;
  const std::vector<std::size_t> fid = set.select(Role::kFiducial);
  for (const std::size_t c : model.procedure2.registration_fiducials) {
    out.strategy3_corners.push_back(fid[c]);
  }

  const RrbcRunOptions run = per_label_options(options);
  for (const int m : out.configs) {
    out.entries.push_back(per_label(set, m, 1, run));
    out.entries.push_back(per_label(ordered.set, m, 2, run));
    out.entries.push_back(strategy3(set, m, model, options, out.sigma_noise_m));
  }
  return out;
}

}  // namespace vrreg::experiments
