// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/adaptive_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "parallel_tasks.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/plan_next_correction.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"
#include "vrreg/planning/arm_configuration.hpp"
#include "vrreg/planning/dmin_criterion.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg/planning/plan_next.hpp"
#include "vrreg/simulation/dataset_plan.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::experiments {
// Unity builds share one translation unit per module: the helpers live in their own namespace.
namespace adaptive_study_detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The paper's cube edges of dataset B, 50 to 5 mm (section 4.1).
std::vector<double> dataset_b_edges_m() {
  std::vector<double> out;
  for (int edge_mm = 50; edge_mm >= 5; edge_mm -= 5) out.push_back(1e-3 * edge_mm);
  return out;
}

// One test bed with its part points (the paper's targets) and their joints.
struct Cell {
  simulation::Testbed testbed;
  planning::ArmConfigurationOptions arm{};
  std::vector<planning::PartPoint> parts{};
  std::vector<kinematics::JointVector> part_q_rad{};
  std::vector<Eigen::Vector3d> grid_m{};  ///< the dataset's fiducials (the full grid)
  double grid_spacing_m = 0.0;
};

Cell make_cell(const std::string& robot) {
  Cell c{simulation::testbed_by_name(robot)};
  c.arm.R_base_tcp = c.testbed.tcp_rotation;
  c.arm.psi_rad = c.testbed.arm_angle_rad;
  c.arm.home_q_rad = c.testbed.home_q_rad;
  const simulation::Dataset dataset = c.testbed.kind == simulation::TestbedKind::kUr5
                                          ? simulation::Dataset::kA1
                                          : simulation::Dataset::kGrid;
  c.grid_spacing_m = simulation::grid_spec(dataset).step_m;
  for (const simulation::PlannedLocation& l : simulation::plan_dataset(c.testbed, dataset)) {
    if (l.role == Role::kTarget) {
      const planning::JointChoice q = planning::part_joints(c.testbed.nominal, l.robot_m, c.arm);
      VRREG_THROW_UNLESS(q.ok(), "adaptive study: target " << l.point << " of " << robot
                                                           << " has no joints: " << q.message);
      c.parts.push_back({l.point, l.robot_m});
      c.part_q_rad.push_back(q.q_rad);
    } else if (l.role == Role::kFiducial) {
      c.grid_m.push_back(l.robot_m);
    }
  }
  return c;
}

std::size_t nearest_part(const Cell& cell, const Eigen::Vector3d& p_m) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < cell.parts.size(); ++i) {
    if ((cell.parts[i].robot_m - p_m).squaredNorm() <
        (cell.parts[best].robot_m - p_m).squaredNorm()) {
      best = i;
    }
  }
  return best;
}

// Measures `plan` on the cell's robot of `seed`; `time_s` gives each acquisition noise of its own.
MeasurementSet measure(const Cell& cell, const std::vector<simulation::CommandedLocation>& plan,
                       std::uint64_t seed, double time_s, long long& n_readings) {
  simulation::SimulationOptions o;
  o.seed = seed;
  o.time_s = time_s;
  const simulation::SimulatedDataset data = simulation::simulate_plan(cell.testbed, plan, o);
  n_readings = static_cast<long long>(data.readings.size());
  return to_measurement_set(data);
}

simulation::CommandedLocation commanded(const std::string& name, Role role,
                                        const Eigen::Vector3d& robot_m,
                                        const kinematics::JointVector& q_rad) {
  simulation::CommandedLocation c;
  c.point = name;
  c.role = role;
  c.robot_m = robot_m;
  c.q_rad = q_rad;
  return c;
}

RegisterOptions register_options(const Cell& cell, InterpolationMethod method,
                                 double cube_edge_m = 0.0) {
  RegisterOptions o;
  o.robot = cell.testbed.nominal;  // the joint-space model reads the joints on this arm
  o.rigid_body_statistics = false;  // sigma_L is not what the study compares
  o.interpolation.method = method;
  o.interpolation.cube_edge_m = cube_edge_m;
  return o;
}

double corrected_rms_t_m(const Cell& cell, const MeasurementSet& fiducials,
                         const MeasurementSet& targets, InterpolationMethod method,
                         double cube_edge_m = 0.0, std::string* method_used = nullptr) {
  const RegisterResult reg =
      register_fiducials(fiducials, register_options(cell, method, cube_edge_m));
  const EvaluateResult e = evaluate(reg.model, targets);
  if (method_used) *method_used = to_string(e.interpolation.method);
  // Over every target: one outside the method's support counts uncorrected (cor_tre_m keeps
  // its registered TRE), not left out (a model that corrects none would score 0).
  return std::sqrt(e.cor_tre_m.squaredNorm() / static_cast<double>(e.cor_tre_m.size()));
}

double robot_time_s(const AdaptiveStudyOptions& o, long long moves, long long readings) {
  return static_cast<double>(moves) * o.seconds_per_move +
         static_cast<double>(readings) * o.seconds_per_reading;
}

// Procedure 1 at cube edge a: the octuplet around every part point (half-width a/2, spacing a).
FixedPlanRun procedure1(const Cell& cell, const AdaptiveStudyOptions& o, std::uint64_t seed,
                        const MeasurementSet& targets, double edge_m, double time_s) {
  planning::PlanOptions po;
  po.halfwidth_m = 0.5 * edge_m;
  po.spacing_m = edge_m;
  po.sigma_noise_m = cell.testbed.kind == simulation::TestbedKind::kLwr4
                         ? planning::kPaperKukaSigmaNoiseM
                         : planning::kPaperSigmaNoiseM;
  po.arm = cell.arm;
  const planning::PlanResult plan = planning::make_plan(cell.testbed.nominal, cell.parts, po);
  VRREG_THROW_UNLESS(plan.ok(), "adaptive study: Procedure 1 at a = "
                                    << 1e3 * edge_m << " mm on " << cell.testbed.name << ": "
                                    << plan.message);
  std::vector<simulation::CommandedLocation> locations;
  for (const planning::PlannedLocation& l : plan.locations) {
    if (l.role == Role::kFiducial)
      locations.push_back(commanded(l.point, l.role, l.robot_m, l.q_rad));
  }
  FixedPlanRun run{cell.testbed.name, seed, "procedure1", edge_m, std::sqrt(3.0) / 2.0 * edge_m,
                   "octuplet"};
  const MeasurementSet set = measure(cell, locations, seed, time_s, run.n_readings);
  run.n_fiducials = static_cast<int>(locations.size());
  run.robot_time_s = robot_time_s(o, run.n_fiducials, run.n_readings);
  run.rms_t_m = corrected_rms_t_m(cell, set, targets, InterpolationMethod::kOctuplet, edge_m);
  return run;
}

// The full grid: every fiducial of the paper's grid dataset, each in its nearest target's
// configuration, registered with kriging.
FixedPlanRun full_grid(const Cell& cell, const AdaptiveStudyOptions& o, std::uint64_t seed,
                       const MeasurementSet& targets, double time_s) {
  std::vector<simulation::CommandedLocation> locations;
  for (std::size_t i = 0; i < cell.grid_m.size(); ++i) {
    const planning::JointChoice q = planning::nearest_joints(
        cell.testbed.nominal, cell.grid_m[i], cell.part_q_rad[nearest_part(cell, cell.grid_m[i])],
        cell.arm);
    if (!q.ok()) continue;  // a grid node out of the targets' configuration is not measured
    locations.push_back(
        commanded("g" + std::to_string(i + 1), Role::kFiducial, cell.grid_m[i], q.q_rad));
  }
  FixedPlanRun run{cell.testbed.name, seed, "grid", cell.grid_spacing_m, 0.0};
  const MeasurementSet set = measure(cell, locations, seed, time_s, run.n_readings);
  run.n_fiducials = static_cast<int>(locations.size());
  run.robot_time_s = robot_time_s(o, run.n_fiducials, run.n_readings);
  run.rms_t_m = corrected_rms_t_m(cell, set, targets, o.interpolation, 0.0, &run.interpolation);
  return run;
}

void append(MeasurementSet& all, const MeasurementSet& more) {
  if (all.locations.empty()) {
    all = more;
    return;
  }
  const std::size_t offset = all.locations.size();
  for (Location l : more.locations) {
    l.source_line += offset;
    all.locations.push_back(std::move(l));
  }
}

// plan next -> measure -> register -> plan next until the loop stops.
AdaptiveRun adaptive_loop(const Cell& cell, const AdaptiveStudyOptions& o, std::uint64_t seed,
                          const MeasurementSet& targets, double goal_sd_m, int budget,
                          double& time_s) {
  AdaptiveRun run{cell.testbed.name, seed};
  planning::PlanNextOptions po;
  po.goal_sd_m = goal_sd_m;
  po.batch_size = o.batch_size;
  po.budget = budget;
  po.candidate_spacing_m = o.candidate_spacing_m;
  po.min_relative_gain = o.min_relative_gain;
  po.arm = cell.arm;
  MeasurementSet all;
  all.source = "adaptive";
  long long readings = 0;
  for (int batch = 1;; ++batch) {
    planning::MeasuredFiducials measured;
    if (!all.locations.empty()) {
      planning::FiducialsWithNoise m = planning::measured_fiducials(all);
      measured = std::move(m.fiducials);
      po.noise_sd_m = m.noise_sd_m;
      if (o.interpolation != InterpolationMethod::kKriging) {
        po.correction_sd = correction_sd_at_parts(all, register_options(cell, o.interpolation));
      }
    }
    const planning::PlanNextResult next =
        planning::plan_next(cell.testbed.nominal, cell.parts, measured, po);
    VRREG_THROW_UNLESS(next.ok(), "adaptive study: " << cell.testbed.name << ": " << next.message);
    if (!all.locations.empty()) {
      AdaptiveBatch b;
      b.batch = batch - 1;
      b.n_fiducials = static_cast<int>(measured.robot_m.cols());
      b.n_readings = readings;
      b.robot_time_s = robot_time_s(o, b.n_fiducials, readings);
      b.predicted_rms_t_m = next.has_model ? next.rms_sd_now_m : kNaN;
      if (next.has_model) b.predicted_by = next.sd_method;
      b.prediction_note = next.sd_note;
      const bool last = next.decision == planning::PlanNextDecision::kStop;
      b.measured_rms_t_m = kNaN;
      if (b.n_fiducials >= po.min_fit_fiducials && (o.measure_every_batch || last)) {
        try {
          b.measured_rms_t_m =
              corrected_rms_t_m(cell, all, targets, o.interpolation, 0.0, &run.interpolation);
        } catch (const InputError&) {
          // Too few fiducials for the method yet (the joint-space model needs 3 equations per
          // parameter): not measured at this batch; at STOP it is an error.
          if (last) throw;
        }
      }
      run.batches.push_back(b);
    }
    if (next.decision == planning::PlanNextDecision::kStop) {
      run.stop_reason = next.reason;
      break;
    }
    std::vector<simulation::CommandedLocation> locations;
    for (const planning::PlannedLocation& l : next.locations)
      locations.push_back(commanded(l.point, Role::kFiducial, l.robot_m, l.q_rad));
    long long n = 0;
    time_s += 1.0;
    append(all, measure(cell, locations, seed, time_s, n));
    readings += n;
  }
  return run;
}

struct SeedOutcome {
  AdaptiveRun adaptive{};
  std::vector<FixedPlanRun> fixed{};
  AdaptiveVerdict verdict{};
};

SeedOutcome run_seed(const Cell& cell, const AdaptiveStudyOptions& o, std::uint64_t seed) {
  SeedOutcome out;
  // The targets once, at time 0; every plan is evaluated at these readings.
  std::vector<simulation::CommandedLocation> target_plan;
  for (std::size_t i = 0; i < cell.parts.size(); ++i) {
    target_plan.push_back(
        commanded(cell.parts[i].name, Role::kTarget, cell.parts[i].robot_m, cell.part_q_rad[i]));
  }
  long long unused = 0;
  const MeasurementSet targets = measure(cell, target_plan, seed, 0.0, unused);
  double time_s = 0.0;  // each acquisition a second apart: noise of its own
  const std::vector<double> edges = o.cube_edges_m.empty() ? dataset_b_edges_m() : o.cube_edges_m;
  for (const double edge_m : edges) {
    time_s += 1.0;
    out.fixed.push_back(procedure1(cell, o, seed, targets, edge_m, time_s));
  }
  if (o.grid) {
    time_s += 1.0;
    out.fixed.push_back(full_grid(cell, o, seed, targets, time_s));
  }
  // d_min: the smallest cube edge.
  const auto dmin = std::min_element(
      out.fixed.begin(), out.fixed.begin() + static_cast<std::ptrdiff_t>(edges.size()),
      [](const FixedPlanRun& a, const FixedPlanRun& b) { return a.cube_edge_m < b.cube_edge_m; });
  const int budget = o.budget > 0 ? o.budget : dmin->n_fiducials / 4;
  const double goal_sd_m = o.goal_sd_m.value_or(1.1 * dmin->rms_t_m);
  out.adaptive = adaptive_loop(cell, o, seed, targets, goal_sd_m, budget, time_s);

  AdaptiveVerdict& v = out.verdict;
  v.robot = cell.testbed.name;
  v.seed = seed;
  v.procedure1_dmin_rms_t_m = dmin->rms_t_m;
  v.procedure1_dmin_fiducials = dmin->n_fiducials;
  v.goal_sd_m = goal_sd_m;
  if (!out.adaptive.batches.empty()) {
    v.adaptive_rms_t_m = out.adaptive.batches.back().measured_rms_t_m;
    v.adaptive_fiducials = out.adaptive.batches.back().n_fiducials;
  }
  v.measured_over_predicted = out.adaptive.measured_over_predicted();
  v.reaches = v.adaptive_rms_t_m <= 1.1 * v.procedure1_dmin_rms_t_m;
  v.quarter = 4 * v.adaptive_fiducials <= v.procedure1_dmin_fiducials;
  v.honest = v.measured_over_predicted >= 0.8 && v.measured_over_predicted <= 1.2;
  return out;
}

}  // namespace
}  // namespace adaptive_study_detail

void AdaptiveStudyOptions::validate() const {
  VRREG_THROW_UNLESS(!robots.empty(), "adaptive study: no robot");
  for (const std::string& r : robots) (void)simulation::testbed_by_name(r);
  VRREG_THROW_UNLESS(!seeds.empty(), "adaptive study: no seed");
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  VRREG_THROW_UNLESS(std::isfinite(seconds_per_move) && seconds_per_move >= 0.0,
                     "adaptive study: seconds per move must be finite and >= 0, got "
                         << seconds_per_move);
  VRREG_THROW_UNLESS(std::isfinite(seconds_per_reading) && seconds_per_reading >= 0.0,
                     "adaptive study: seconds per reading must be finite and >= 0, got "
                         << seconds_per_reading);
  VRREG_THROW_UNLESS(batch_size >= 1, "adaptive study: batch size must be >= 1, got " << batch_size);
  VRREG_THROW_UNLESS(budget >= 0, "adaptive study: budget must be >= 0, got " << budget);
  VRREG_THROW_UNLESS(!goal_sd_m || positive(*goal_sd_m), "adaptive study: the goal must be positive");
  VRREG_THROW_UNLESS(positive(candidate_spacing_m),
                     "adaptive study: the candidate spacing must be positive");
  VRREG_THROW_UNLESS(
      std::isfinite(min_relative_gain) && min_relative_gain >= 0.0 && min_relative_gain < 1.0,
      "adaptive study: the minimum relative gain must be in [0, 1), got " << min_relative_gain);
  for (const double a : cube_edges_m) {
    VRREG_THROW_UNLESS(positive(a), "adaptive study: a cube edge must be positive, got " << a);
  }
}

AdaptiveStudyOptions quick_study_options(AdaptiveStudyOptions options) {
  options.cube_edges_m = {0.050, 0.005};
  options.grid = false;
  options.batch_size = 60;
  options.measure_every_batch = false;
  return options;
}

double AdaptiveRun::measured_over_predicted() const {
  if (batches.empty()) return std::numeric_limits<double>::quiet_NaN();
  return batches.back().measured_rms_t_m / batches.back().predicted_rms_t_m;
}

AdaptiveStudyResult run_adaptive_study(const AdaptiveStudyOptions& options) {
  using namespace adaptive_study_detail;
  options.validate();
  AdaptiveStudyResult result;
  result.options = options;
  const std::size_t n_seeds = options.seeds.size();
  std::vector<Cell> cells;
  for (const std::string& robot : options.robots) {
    cells.push_back(make_cell(robot));
    result.n_targets.push_back(static_cast<int>(cells.back().parts.size()));
  }
  // Every (robot, seed) in parallel; the results robot-major, the same for any thread count.
  std::vector<SeedOutcome> outcomes(cells.size() * n_seeds);
  detail::parallel_tasks(outcomes.size(), [&](std::size_t k) {
    outcomes[k] = run_seed(cells[k / n_seeds], options, options.seeds[k % n_seeds]);
  });
  for (SeedOutcome& s : outcomes) {
    result.adaptive.push_back(std::move(s.adaptive));
    for (FixedPlanRun& f : s.fixed) result.fixed.push_back(std::move(f));
    result.verdicts.push_back(s.verdict);
  }
  return result;
}

}  // namespace vrreg::experiments
