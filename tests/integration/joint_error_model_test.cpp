// SPDX-License-Identifier: Apache-2.0
// The joint-space error model end to end on the simulated test beds: A1 (UR5) and the
// KUKA grid with all four arm configurations in one model, against octuplet RRBC and the noise
// floor; and on a Cartesian (not joint-periodic) error field, where it must not fit. Prints the
// numbers docs/joint-space-model.md records.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "joint_error_cells.hpp"
#include "simulation_test_support.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/experiments/table1.hpp"
#include "vrreg/experiments/table2.hpp"
#include "vrreg/simulation/cartesian_error_field.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

constexpr double kMm = 1e3;

simulation::SimulationOptions seeded(std::uint64_t seed) {
  simulation::SimulationOptions o;
  o.seed = seed;
  return o;
}

std::string degrees_text(const std::vector<int>& d) {
  std::string s;
  for (int v : d) s += (s.empty() ? "" : ",") + std::to_string(v);
  return s;
}

// One KUKA grid seed: every fiducial of every configuration in one registration and one model;
// each configuration's targets against RRBC Strategies 2 and 3 and the floor.
void kuka_cell(std::uint64_t seed) {
  const simulation::Testbed lwr4 = simulation::lwr4_testbed();
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(lwr4, simulation::Dataset::kGrid, seeded(seed));
  const MeasurementSet set = experiments::to_measurement_set(data);
  const testing::JointCellOutcome o = testing::joint_model_cell(set, data, lwr4.nominal, {});
  experiments::Table2Options t2;
  t2.strategy3_seed = seed;
  const experiments::Table2 rrbc = experiments::run_table2(set, t2);
  std::printf("KUKA seed %llu: degrees %s, rank %d of %d, residual %.4f mm\n",
              static_cast<unsigned long long>(seed), degrees_text(o.degrees).c_str(), o.rank,
              o.n_parameters, kMm * o.residual_rms_m);
  for (const int config : rrbc.configs) {
    std::vector<Eigen::Index> rows;
    for (std::size_t k = 0; k < o.targets.size(); ++k) {
      if (set.locations[o.targets[k]].config == config)
        rows.push_back(static_cast<Eigen::Index>(k));
    }
    const double cor_m = testing::rms_at(o.cor_tre_m, rows);
    const double floor_m = testing::rms_at(o.floor_tre_m, rows);
    std::printf(
        "KUKA seed %llu config %d: joint model %.4f mm, strategy 2 %.4f mm, strategy 3 %.4f mm, "
        "floor %.4f mm (%zu targets)\n",
        static_cast<unsigned long long>(seed), config, kMm * cor_m,
        kMm * rrbc.at(config, 2).figures.cor_rms_t_m, kMm * rrbc.at(config, 3).figures.cor_rms_t_m,
        kMm * floor_m, rows.size());
    EXPECT_LT(cor_m, 0.125e-3) << "seed " << seed << " config " << config;
    EXPECT_LT(cor_m, rrbc.at(config, 2).figures.cor_rms_t_m)
        << "seed " << seed << " config " << config;
  }
}

TEST(JointErrorModelCells, A1CorrectsToTheNoiseFloor) {
  const simulation::Testbed ur5 = simulation::ur5_testbed();
  std::vector<double> joint;
  // Under the sanitizers one seed exercises the same code (three take ~12 s there).
  const std::uint64_t last_seed = testing::sanitized() ? 1 : 3;
  for (std::uint64_t seed = 1; seed <= last_seed; ++seed) {
    const simulation::SimulatedDataset data =
        simulation::simulate_dataset(ur5, simulation::Dataset::kA1, seeded(seed));
    const MeasurementSet set = experiments::to_measurement_set(data);
    const testing::JointCellOutcome o = testing::joint_model_cell(set, data, ur5.nominal, {});
    experiments::Table1Options t1;
    t1.cube_edge_m = 0.050;
    const double octuplet_m = experiments::run_table1_entry(set, "A1", t1).figures.cor_rms_t_m;
    const double cor_m = root_mean_square(o.cor_tre_m);
    const double floor_m = root_mean_square(o.floor_tre_m);
    std::printf(
        "A1 seed %llu: joint model %.4f mm, octuplet %.4f mm, floor %.4f mm; degrees %s, "
        "rank %d of %d, residual %.4f mm\n",
        static_cast<unsigned long long>(seed), kMm * cor_m, kMm * octuplet_m, kMm * floor_m,
        degrees_text(o.degrees).c_str(), o.rank, o.n_parameters, kMm * o.residual_rms_m);
    EXPECT_LT(cor_m, 0.5 * octuplet_m) << "seed " << seed;
    EXPECT_LT(cor_m, 1.15 * floor_m) << "seed " << seed;
    joint.push_back(cor_m);
  }
  std::sort(joint.begin(), joint.end());
  EXPECT_LT(joint[joint.size() / 2], 0.100e-3);  // the target, median over the seeds
}

TEST(JointErrorModelCells, KukaOneModelForAllFourConfigurations) {
  // Under the sanitizers one seed exercises the same code: each takes ~25 s there.
  const std::uint64_t last_seed = testing::sanitized() ? 1 : 3;
  for (std::uint64_t seed = 1; seed <= last_seed; ++seed) kuka_cell(seed);
}

// A robot that is perfect in joint space, with a smooth + wavy Cartesian error instead (not a
// function of single joint angles): the joint model's trend takes the smooth part, its joint
// functions cannot take the wavy one, and cross-validation says so.
TEST(JointErrorModelCells, CartesianFieldIsNotFittedByTheJointModel) {
  const simulation::Testbed ur5 = simulation::ur5_testbed();
  simulation::SimulationOptions options = seeded(5);
  options.errors = testing::perfect_errors(ur5);
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(ur5, simulation::Dataset::kA1, options);
  MeasurementSet set = experiments::to_measurement_set(data);
  Random rng(51);
  const CartesianErrorField field =
      CartesianErrorField::random(rng, ur5.volume_centre_m, 0.15, 0.6e-3, 0.15e-3);
  constexpr double kNoise = 0.02e-3;   // per axis, the size of A1's mean-of-12 tracker noise
  for (Location& l : set.locations) {  // sensor frame = robot frame, so the registration is ~I
    l.sensor_m = l.robot_m + field.error_m(l.robot_m) + rng.normal3(kNoise);
  }
  const std::vector<std::size_t> fid = set.select(Role::kFiducial);
  const std::vector<std::size_t> tgt = set.select(Role::kTarget);
  const Points3 fid_robot = set.robot_points(fid);
  const RigidTransform T = register_rigid(set.sensor_points(fid), fid_robot).T_robot_sensor.rigid();
  const Points3 e_fid = T.apply_all(set.sensor_points(fid)) - fid_robot;
  const std::vector<kinematics::JointVector> q_fid = testing::joints_of(set, fid);
  const kinematics::JointErrorModel model =
      kinematics::JointErrorModel::fit(ur5.nominal, q_fid, e_fid);
  const double cv_m = kinematics::joint_error_cv_rms_m(ur5.nominal, q_fid, e_fid);
  const Points3 tgt_robot = set.robot_points(tgt);
  const double joint_m = root_mean_square(point_errors(
      T.apply_all(set.sensor_points(tgt)) - model.predict_m(testing::joints_of(set, tgt)),
      tgt_robot));
  experiments::RrbcRunOptions grid;
  grid.interpolation.method = InterpolationMethod::kGrid;
  grid.rigid_body_statistics = false;
  grid.sigma_opt_m = kNoise;
  const double grid_m = experiments::run_rrbc(set, fid, tgt, grid).cor_rms_t_m;
  const double noise_m = std::sqrt(3.0) * kNoise;
  CartesianErrorField smooth = field;
  for (CartesianErrorField::Wave& w : smooth.waves) w.amplitude_m.setZero();
  double wavy_sq = 0.0;
  for (Eigen::Index j = 0; j < fid_robot.cols(); ++j) {
    wavy_sq += (field.error_m(fid_robot.col(j)) - smooth.error_m(fid_robot.col(j))).squaredNorm();
  }
  const double wavy_m = std::sqrt(wavy_sq / static_cast<double>(fid_robot.cols()));
  std::printf(
      "Cartesian field: joint model %.4f mm (CV %.4f mm, degrees %s), trilinear grid "
      "%.4f mm, wavy part %.4f mm, noise %.4f mm\n",
      kMm * joint_m, kMm * cv_m, degrees_text(model.joint_degrees()).c_str(), kMm * grid_m,
      kMm * wavy_m, kMm * noise_m);
  // The wavy part stays in the cross-validated error: the model does not pretend to fit it.
  EXPECT_GT(cv_m, 3.0 * noise_m);
  EXPECT_GT(cv_m, 0.7 * wavy_m);
  EXPECT_GT(joint_m, 0.7 * wavy_m);
}

}  // namespace
}  // namespace vrreg
