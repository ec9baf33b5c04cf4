// SPDX-License-Identifier: Apache-2.0
// The front door on arrays (names, configs, joints, repeats given as MeasuredPoints) gives exactly
// what it gives on the same locations read from a measurement file, with Procedure 2's strategies.
#include <gtest/gtest.h>

#include <sstream>

#include "two_arm_cell.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/vrreg.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

// The locations of `set` with `role`, as arrays.
MeasuredPoints arrays_of(const MeasurementSet& set, Role role) {
  const std::vector<std::size_t> rows = set.select(role);
  MeasuredPoints p;
  p.sensor_m = set.sensor_points(rows);
  p.robot_m = set.robot_points(rows);
  const auto n = static_cast<Eigen::Index>(rows.size());
  p.joints_rad.resize(set.n_joints, n);
  p.n_readings.resize(n);
  p.sensor_sq_dev_m2.resize(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Location& loc = set.locations[rows[static_cast<std::size_t>(k)]];
    p.names.push_back(loc.point);
    p.configs.push_back(*loc.config);
    p.joints_rad.col(k) = Eigen::Map<const Eigen::VectorXd>(loc.q_rad.data(), set.n_joints);
    p.n_readings(k) = loc.n_readings;
    p.sensor_sq_dev_m2.col(k) = loc.sensor_sq_dev_m2;
  }
  return p;
}

class ArraysVsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    std::istringstream in(testing::two_arm_cell_csv());
    file = io::parse_measurement_csv(in, "arms.csv");
    fiducials = arrays_of(file, Role::kFiducial);
    targets = arrays_of(file, Role::kTarget);
  }
  MeasurementSet file;
  MeasuredPoints fiducials, targets;
};

void expect_same_model(const RegisterResult& a, const RegisterResult& b) {
  EXPECT_EIGEN_NEAR(a.model.T_robot_sensor.rotation, b.model.T_robot_sensor.rotation, 0.0);
  EXPECT_EIGEN_NEAR(a.model.T_robot_sensor.translation_m, b.model.T_robot_sensor.translation_m,
                    0.0);
  EXPECT_EIGEN_NEAR(a.model.corrections_sensor_m, b.model.corrections_sensor_m, 0.0);
  EXPECT_EQ(a.rigid_body.sigma_l_m, b.rigid_body.sigma_l_m);
  EXPECT_EQ(a.noise.sigma_opt_m, b.noise.sigma_opt_m);
}

TEST_F(ArraysVsFile, Strategy1OneConfiguration) {
  RegisterOptions options;
  options.config = 2;
  options.procedure2.strategy = planning::Strategy::kAsListed;
  const RegisterResult from_file = register_fiducials(file, options);
  const RegisterResult from_arrays = register_fiducials(fiducials, options);
  expect_same_model(from_file, from_arrays);
  EXPECT_EQ(from_arrays.n_registered, 117u);
  EvaluateOptions cube;
  cube.interpolation.cube_edge_m = 0.04;
  const EvaluateResult e_file = evaluate(from_file.model, file, cube);
  const EvaluateResult e_arrays = evaluate(from_arrays.model, targets, cube);
  EXPECT_EQ(e_arrays.config, 2) << "the model's configuration";
  EXPECT_EQ(e_arrays.names, e_file.names);
  EXPECT_EIGEN_NEAR(e_arrays.cor_tre_m, e_file.cor_tre_m, 0.0);
}

TEST_F(ArraysVsFile, Strategy3VolumeCorners) {
  RegisterOptions options;
  options.procedure2.strategy = planning::Strategy::kVolumeCorners;
  options.procedure2.seed = 7;
  options.interpolation.method = InterpolationMethod::kOctuplet;
  options.interpolation.cube_edge_m = 0.04;
  const RegisterResult from_file = register_fiducials(file, options);
  const RegisterResult from_arrays = register_fiducials(fiducials, options);
  expect_same_model(from_file, from_arrays);
  EXPECT_EQ(from_arrays.model.procedure2.registration_fiducials,
            from_file.model.procedure2.registration_fiducials);
  for (const int config : {1, 2}) {
    EvaluateOptions one;
    one.config = config;
    const EvaluateResult e_file = evaluate(from_file.model, file, one);
    const EvaluateResult e_arrays = evaluate(from_arrays.model, targets, one);
    ASSERT_EQ(e_arrays.summary.n_targets, 8);
    EXPECT_EIGEN_NEAR(e_arrays.cor_tre_m, e_file.cor_tre_m, 0.0);
    CorrectOptions correct_one;
    correct_one.config = config;
    const CorrectResult c = correct(from_arrays.model, targets, correct_one);
    EXPECT_EIGEN_NEAR(c.correction.corrected_robot_m, e_file.correction.corrected_robot_m, 0.0);
  }
}

TEST_F(ArraysVsFile, Strategy2NeedsLabelsAndJoints) {
  RegisterOptions options;
  options.config = 1;
  options.procedure2.strategy = planning::Strategy::kAlongPath;
  const RegisterResult r = register_fiducials(fiducials, options);
  ASSERT_TRUE(r.relabelled);
  EXPECT_GT(r.relabelled->n_switched, 0);
  MeasuredPoints unlabelled = fiducials;
  unlabelled.configs.clear();
  try {
    (void)register_fiducials(unlabelled, options);
    ADD_FAILURE() << "Strategy 2 without configuration labels was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("config column"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vrreg
