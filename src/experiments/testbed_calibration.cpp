#include "vrreg/experiments/testbed_calibration.hpp"

#include <chrono>
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/experiments/strategy2.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/improvement.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg::experiments {
namespace {

using simulation::Dataset;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

RrbcRunOptions octuplet(double cube_edge_m, double sigma_rep_m) {
  RrbcRunOptions options;
  options.interpolation.method = InterpolationMethod::kOctuplet;
  options.interpolation.cube_edge_m = cube_edge_m;
  options.sigma_rep_m = sigma_rep_m;
  return options;
}

RrbcRunFigures run_grid_dataset(const simulation::Testbed& testbed, Dataset dataset,
                                std::uint64_t seed,
                                const std::optional<simulation::TestbedErrorModel>& errors,
                                double cube_edge_m) {
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, dataset, {seed, errors});
  const MeasurementSet set = to_measurement_set(data);
  return run_rrbc(set, set.select(Role::kFiducial), set.select(Role::kTarget),
                  octuplet(cube_edge_m, testbed.sigma_rep_spec_m));
}

// Dataset B (section 4.3): one registration from all 9600 fiducials; each target corrected from
// the eight corners of each of its ten cubes in turn (weights 1/8).
void run_b(const simulation::Testbed& testbed, std::uint64_t seed,
           const std::optional<simulation::TestbedErrorModel>& errors, Ur5SeedFigures& out) {
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, Dataset::kB, {seed, errors});
  const MeasurementSet set = to_measurement_set(data);
  const std::vector<std::size_t> fid = set.select(Role::kFiducial);
  const std::vector<std::size_t> tgt = set.select(Role::kTarget);
  const Points3 fid_sensor = set.sensor_points(fid);
  const Points3 fid_robot = set.robot_points(fid);
  const RigidTransform T = register_rigid(fid_sensor, fid_robot).T_robot_sensor;
  const Points3 eps = fiducial_corrections(T, fid_sensor, fid_robot);

  // Sum of corrections per (target, cube edge); edges are 50, 45, ..., 5 mm.
  constexpr int kCubes = 10;
  std::vector<int> target_slot(set.locations.size(), -1);
  for (std::size_t t = 0; t < tgt.size(); ++t) target_slot[tgt[t]] = static_cast<int>(t);
  std::vector<Eigen::Vector3d> sum(tgt.size() * kCubes, Eigen::Vector3d::Zero());
  std::vector<int> count(tgt.size() * kCubes, 0);
  for (std::size_t j = 0; j < fid.size(); ++j) {
    const simulation::PlannedLocation& p = data.locations[fid[j]];
    const int slot = target_slot[static_cast<std::size_t>(p.owner)];
    const int cube = static_cast<int>(std::lround((0.050 - p.cube_edge_m) / 0.005));
    VRREG_THROW_UNLESS(slot >= 0 && cube >= 0 && cube < kCubes,
                       "dataset B: bad fiducial " << p.point);
    const auto k = static_cast<std::size_t>(slot * kCubes + cube);
    sum[k] += eps.col(static_cast<Eigen::Index>(j));
    ++count[k];
  }
  const Points3 tgt_sensor = set.sensor_points(tgt);
  const Points3 tgt_robot = set.robot_points(tgt);
  const Eigen::VectorXd unc = point_errors(T.apply_all(tgt_sensor), tgt_robot);
  out.b_unc_rms_t_m = root_mean_square(unc);
  for (int cube = 0; cube < kCubes; ++cube) {
    Points3 corrected = tgt_sensor;
    for (std::size_t t = 0; t < tgt.size(); ++t) {
      const auto k = t * kCubes + static_cast<std::size_t>(cube);
      VRREG_THROW_UNLESS(count[k] == 8, "dataset B: target " << t << " cube " << cube << " has "
                                                             << count[k] << " corners");
      corrected.col(static_cast<Eigen::Index>(t)) += sum[k] / 8.0;
    }
    const Eigen::VectorXd cor = point_errors(T.apply_all(corrected), tgt_robot);
    const ImprovementSummary s = summarize_improvement(unc, cor);
    out.b_cube_edge_m.push_back(0.050 - 0.005 * cube);
    out.b_cor_rms_t_m.push_back(s.cor_rms_t_m);
    out.b_n_bad.push_back(s.n_bad);
  }
}

// Strategy 2 labels for the visits of an LWR dataset (four visits per point, in label order).
MeasurementSet relabel_strategy2(const MeasurementSet& set, std::size_t per_point,
                                 double& switched) {
  std::vector<Eigen::MatrixXd> configurations;
  for (std::size_t first = 0; first < set.locations.size(); first += per_point) {
    Eigen::MatrixXd q(set.n_joints, static_cast<Eigen::Index>(per_point));
    for (std::size_t m = 0; m < per_point; ++m) {
      const std::vector<double>& qm = set.locations[first + m].q_rad;
      for (int i = 0; i < set.n_joints; ++i)
        q(i, static_cast<Eigen::Index>(m)) = qm[static_cast<std::size_t>(i)];
    }
    configurations.push_back(std::move(q));
  }
  const std::vector<std::vector<int>> order = strategy2_order(configurations);
  switched = switched_fraction(order);
  MeasurementSet out = set;
  for (std::size_t p = 0; p < order.size(); ++p) {
    for (std::size_t m = 0; m < per_point; ++m) {
      out.locations[p * per_point + static_cast<std::size_t>(order[p][m])].config =
          static_cast<int>(m) + 1;
    }
  }
  return out;
}

std::array<RrbcRunFigures, 4> run_per_label(const MeasurementSet& set,
                                            const RrbcRunOptions& options) {
  std::array<RrbcRunFigures, 4> out;
  for (int m = 1; m <= 4; ++m) {
    out[static_cast<std::size_t>(m - 1)] =
        run_rrbc(set, set.select(Role::kFiducial, m), set.select(Role::kTarget, m), options);
  }
  return out;
}

}  // namespace

Ur5SeedFigures calibrate_ur5(const simulation::Testbed& testbed, std::uint64_t seed,
                             const std::optional<simulation::TestbedErrorModel>& errors) {
  const Clock::time_point start = Clock::now();
  Ur5SeedFigures f;
  f.seed = seed;
  f.a1 = run_grid_dataset(testbed, Dataset::kA1, seed, errors, 0.050);
  f.a2 = run_grid_dataset(testbed, Dataset::kA2, seed, errors, 0.025);
  run_b(testbed, seed, errors, f);
  f.seconds = seconds_since(start);
  return f;
}

Lwr4SeedFigures calibrate_lwr4(const simulation::Testbed& testbed, std::uint64_t seed,
                               const std::optional<simulation::TestbedErrorModel>& errors,
                               double sigma_opt_m) {
  const Clock::time_point start = Clock::now();
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, Dataset::kGrid, {seed, errors});
  const MeasurementSet set = to_measurement_set(data);
  RrbcRunOptions options = octuplet(0.040, testbed.sigma_rep_spec_m);
  options.sigma_opt_m = sigma_opt_m;
  Lwr4SeedFigures f;
  f.seed = seed;
  f.strategy1 = run_per_label(set, options);
  f.strategy2 = run_per_label(relabel_strategy2(set, 4, f.switched_fraction), options);
  f.seconds = seconds_since(start);
  return f;
}

CalibrationReport run_testbed_calibration(const CalibrationOptions& options) {
  VRREG_THROW_UNLESS(!options.seeds.empty(), "calibration: no seeds");
  CalibrationReport report;
  const simulation::Testbed ur5 = simulation::ur5_testbed();
  const simulation::Testbed lwr4 = simulation::lwr4_testbed();
  for (std::uint64_t seed : options.seeds) {
    double sigma_opt = lwr4.default_errors.tracker.noise_sigma_m.norm() / std::sqrt(3.0);
    if (options.lwr4_errors)
      sigma_opt = options.lwr4_errors->tracker.noise_sigma_m.norm() / std::sqrt(3.0);
    if (options.ur5) {
      report.ur5.push_back(calibrate_ur5(ur5, seed, options.ur5_errors));
      sigma_opt = report.ur5.back().a1.sigma_opt_m;
    }
    if (options.lwr4)
      report.lwr4.push_back(calibrate_lwr4(lwr4, seed, options.lwr4_errors, sigma_opt));
  }
  return report;
}

}  // namespace vrreg::experiments
