// SPDX-License-Identifier: Apache-2.0
// Simulated test beds through the whole pipeline: measurement files, registration, Strategy 2 and
// the calibration against the paper (docs/testbed-calibration.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "simulation_test_support.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/experiments/testbed_calibration.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/metrics/rigid_body.hpp"
#include "vrreg/planning/strategy2_labels.hpp"
#include "vrreg/registration/rigid.hpp"
#include "vrreg/robot_io/simulation_csv.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using simulation::Dataset;

using testing::perfect_errors;

std::string csv_text(const simulation::SimulatedDataset& data) {
  return io::format_measurement_csv(io::simulated_readings(data),
                                    io::simulated_dataset_comments(data));
}

TEST(SimulationPipeline, PerfectTestbedGivesRigidDataAndTheTrackerPoseBack) {
  const simulation::Testbed testbed = simulation::ur5_testbed();
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, Dataset::kA1, {9, perfect_errors(testbed)});
  std::istringstream in(csv_text(data));
  const MeasurementSet set = io::parse_measurement_csv(in, "perfect.csv");
  ASSERT_EQ(set.locations.size(), 1287u);
  const std::vector<std::size_t> fid = set.select(Role::kFiducial);
  ASSERT_EQ(fid.size(), 1167u);
  const Points3 sensor = set.sensor_points(fid);
  const Points3 robot = set.robot_points(fid);
  EXPECT_LE(rigid_body_statistics(sensor, robot).sigma_l_m, 1e-12);  // 1e-9 mm
  const RegistrationResult reg = register_rigid(sensor, robot);
  EXPECT_EIGEN_NEAR(reg.T_robot_sensor.rotation, data.T_robot_sensor.rotation, 1e-12);
  EXPECT_EIGEN_NEAR(reg.T_robot_sensor.translation_m, data.T_robot_sensor.translation_m, 1e-9);
  EXPECT_LE(reg.fre_m, 1e-12);
}

TEST(SimulationPipeline, SameSeedSameBytes) {
  const simulation::Testbed testbed = simulation::ur5_testbed();
  const std::string a = csv_text(simulation::simulate_dataset(testbed, Dataset::kA1, {42, {}}));
  const std::string b = csv_text(simulation::simulate_dataset(testbed, Dataset::kA1, {42, {}}));
  const std::string c = csv_text(simulation::simulate_dataset(testbed, Dataset::kA1, {43, {}}));
  EXPECT_TRUE(a == b);
  EXPECT_FALSE(a == c);
  // The file written to disk is that text.
  const auto path =
      std::filesystem::temp_directory_path() / ("vrreg_sim_" + std::to_string(::getpid()) + ".csv");
  io::write_simulated_dataset_csv(path.string(),
                                  simulation::simulate_dataset(testbed, Dataset::kA1, {42, {}}));
  std::ifstream file(path, std::ios::binary);
  const std::string written{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  std::filesystem::remove(path);
  EXPECT_TRUE(written == a);
}

TEST(SimulationPipeline, HeaderStatesTestbedDatasetSeedAndEveryParameter) {
  const simulation::Testbed testbed = simulation::lwr4_testbed();
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(testbed, Dataset::kGrid, {17, {}});
  const std::string text = csv_text(data);
  for (const char* fragment :
       {"test bed lwr4, dataset grid, seed 17", "joint offset sigma 0.25 deg",
        "link length (a) sigma", "link offset (d) sigma", "twist (alpha) sigma", "A_arcmin [0.75",
        "P_deg [20, 18, 24", "repeatability sigma 0.03 mm", "compliance under gravity on",
        "1.8 m from the volume centre", "[0.058, 0.058, 0.058] mm", "K = 1 readings",
        "joint 7: dtheta", "T_robot_sensor"}) {
    EXPECT_NE(text.find(fragment), std::string::npos) << fragment;
  }
  std::istringstream in(text);
  const MeasurementSet set = io::parse_measurement_csv(in, "grid.csv");
  EXPECT_EQ(set.locations.size(), 4u * 1573u);
  EXPECT_EQ(set.n_joints, 7);
  EXPECT_TRUE(set.has_config);
  EXPECT_EQ(set.select(Role::kTarget, 1).size(), 150u);
  EXPECT_EQ(set.select(Role::kFiducial, 4).size(), 1423u);
}

TEST(SimulationPipeline, Strategy2ReordersAboutOnePointInSeven) {
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(simulation::lwr4_testbed(), Dataset::kGrid, {1, {}});
  const planning::Strategy2Result r =
      planning::relabel_strategy2(experiments::to_measurement_set(data));
  EXPECT_EQ(r.summary.n_points, 1573);
  EXPECT_EQ(r.summary.n_locations, 4 * 1573);
  EXPECT_GE(r.summary.switched_points_fraction(), 0.10);  // paper: ~14 % of nominal locations
  EXPECT_LE(r.summary.switched_points_fraction(), 0.20);
  EXPECT_LT(r.summary.switched_locations_fraction(), r.summary.switched_points_fraction());
  EXPECT_EQ(r.summary.switched_by_file_label.count(4), 0u)
      << "label 4 is never switched (paper 5.2)";
}

TEST(SimulationPipeline, DefaultParametersMeetTheCalibrationBands) {
  if (testing::sanitized()) GTEST_SKIP() << "ten seeds of every dataset: release builds only";
  const experiments::CalibrationReport report = experiments::run_testbed_calibration({});
  EXPECT_TRUE(experiments::calibration_passes(report))
      << experiments::format_calibration_markdown(report);
}

TEST(SimulationPipeline, OneSeedRunsEveryDatasetWithPlausibleFigures) {
  experiments::CalibrationOptions options;
  options.seeds = {2};
  const experiments::CalibrationReport report = experiments::run_testbed_calibration(options);
  ASSERT_EQ(report.ur5.size(), 1u);
  const experiments::Ur5SeedFigures& u = report.ur5.front();
  EXPECT_NEAR(u.a1.sigma_opt_m, 0.058e-3, 0.003e-3);
  EXPECT_EQ(u.a1.n_targets, 120);
  EXPECT_EQ(u.a2.n_targets, 960);
  EXPECT_EQ(u.a2.n_fiducials, 7965);
  EXPECT_EQ(u.a1.n_flagged, 0);
  EXPECT_LT(u.a2.cor_rms_t_m, u.a1.cor_rms_t_m);
  EXPECT_LT(u.b_cor_rms_t_m.back(), u.b_cor_rms_t_m.front());
  ASSERT_EQ(report.lwr4.size(), 1u);
  for (const auto& f : report.lwr4.front().strategy2) EXPECT_LT(f.cor_rms_t_m, f.unc_rms_t_m);
}

}  // namespace
}  // namespace vrreg
