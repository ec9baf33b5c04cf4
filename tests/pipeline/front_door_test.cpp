// SPDX-License-Identifier: Apache-2.0
// The front door (vrreg/vrreg.hpp) on in-memory arrays: what it computes agrees with independent
// references (Eigen::umeyama, brute-force sigma_L, hand-made trilinear), its parts agree with each
// other (register/evaluate/correct), and bad input is an InputError that says what is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <string>

#include "vrreg/vrreg.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using ::testing::HasSubstr;

/// A smooth robot error [m] at a nominal robot position: the arm lands off by up to ~0.5 mm.
Eigen::Vector3d robot_error_m(const Eigen::Vector3d& p) {
  return Eigen::Vector3d(3e-4 * std::sin(15.0 * p.y()) + 1e-3 * p.x() * p.z(),
                         2e-4 * std::cos(17.0 * p.z()) - 8e-4 * p.x(),
                         2e-4 * std::sin(19.0 * p.x() + 7.0 * p.y()));
}

class FrontDoor : public ::testing::Test {
 protected:
  void SetUp() override {
    fiducials.robot_m = testing::cube_grid_m(5, 0.05);
    targets.robot_m = testing::cube_grid_m(4, 0.05, 0.025);  // the centres of the grid's cubes
    fiducials.sensor_m = measure(fiducials.robot_m);
    targets.sensor_m = measure(targets.robot_m);
  }
  Points3 measure(const Points3& robot_m) const {
    Points3 out(3, robot_m.cols());
    for (Eigen::Index j = 0; j < robot_m.cols(); ++j) {
      out.col(j) =
          T_sensor_robot.apply(Eigen::Vector3d(robot_m.col(j) + robot_error_m(robot_m.col(j))));
    }
    return out;
  }
  Random rng{97};
  RigidTransform T_sensor_robot = testing::random_transform(rng, 2.0);
  MeasuredPoints fiducials, targets;
};

TEST_F(FrontDoor, RegistersAsUmeyamaAndKeepsTheRigidBodyStatistics) {
  const RegisterResult r = register_fiducials(fiducials);
  const Eigen::Matrix4d umeyama = Eigen::umeyama(fiducials.sensor_m, fiducials.robot_m, false);
  const Eigen::Matrix3d umeyama_rotation = umeyama.topLeftCorner(3, 3);
  const Eigen::Vector3d umeyama_translation_m = umeyama.topRightCorner(3, 1);
  EXPECT_EIGEN_NEAR(r.model.T_robot_sensor.rotation, umeyama_rotation, 1e-12);
  EXPECT_EIGEN_NEAR(r.model.T_robot_sensor.translation_m, umeyama_translation_m, 1e-12);
  EXPECT_EQ(r.n_registered, 125u);
  EXPECT_EQ(r.model.fiducials.size(), 125u);
  // sigma_L over all pairs, brute force (Eq. 1).
  double sum = 0, sum2 = 0;
  int pairs = 0;
  for (int i = 0; i < 125; ++i) {
    for (int j = i + 1; j < 125; ++j) {
      const double l = (fiducials.sensor_m.col(i) - fiducials.sensor_m.col(j)).norm() -
                       (fiducials.robot_m.col(i) - fiducials.robot_m.col(j)).norm();
      sum += l;
      sum2 += l * l;
      ++pairs;
    }
  }
  const double sigma_l = std::sqrt((sum2 - sum * sum / pairs) / (pairs - 1));
  EXPECT_NEAR(r.rigid_body.sigma_l_m, sigma_l, 1e-12);
  EXPECT_EQ(r.model.sigma_l_m, r.rigid_body.sigma_l_m);
  EXPECT_FALSE(r.noise.sigma_noise_m) << "no repeats and no sigma_rep: unknown";
  EXPECT_EQ(r.model.fiducials[7].point, "8") << "default names count from 1";
}

// Two point sets as Eigen::umeyama(src, dst) takes them, views into larger matrices included.
TEST_F(FrontDoor, RegistersTwoPointSetsAsUmeyamaDoes) {
  Eigen::MatrixXd both(6, fiducials.size() + 1);
  both.topLeftCorner(3, fiducials.size()) = fiducials.sensor_m;
  both.bottomLeftCorner(3, fiducials.size()) = fiducials.robot_m;
  const RegisterResult r =
      register_fiducials(both.topLeftCorner(3, fiducials.size()),
                         both.bottomLeftCorner(3, fiducials.size()), {.sigma_rep_m = 5e-5});
  const RegisterResult same = register_fiducials(fiducials, {.sigma_rep_m = 5e-5});
  EXPECT_EQ(r.model.T_robot_sensor.rotation, same.model.T_robot_sensor.rotation);
  EXPECT_EQ(r.model.T_robot_sensor.translation_m, same.model.T_robot_sensor.translation_m);
  EXPECT_EQ(r.rigid_body.sigma_l_m, same.rigid_body.sigma_l_m);
  EXPECT_EQ(r.noise.sigma_noise_m, same.noise.sigma_noise_m);
}

TEST_F(FrontDoor, EvaluateAndCorrectAgreeAndRrbcHelps) {
  const RegisterResult r = register_fiducials(fiducials);
  const EvaluateResult e = evaluate(r.model, targets);
  ASSERT_EQ(e.summary.n_targets, 64);
  EXPECT_EQ(e.correction.method_used, InterpolationMethod::kGrid);
  EXPECT_LT(e.summary.cor_rms_t_m, 0.3 * e.summary.unc_rms_t_m);
  // correct() hands the robot exactly what evaluate() measured.
  MeasuredPoints sensed = targets;
  sensed.robot_m.resize(3, 0);  // correcting needs only what the sensor saw
  const CorrectResult c = correct(r.model, sensed);
  EXPECT_EIGEN_NEAR(c.correction.corrected_robot_m, e.correction.corrected_robot_m, 0.0);
  // TRE (Eq. 3) by hand.
  for (Eigen::Index i = 0; i < 64; ++i) {
    EXPECT_NEAR(e.cor_tre_m(i),
                (c.correction.corrected_robot_m.col(i) - targets.robot_m.col(i)).norm(), 1e-15);
  }
  // Octuplet at a cube centre: the mean of the 8 corners' corrections (Eq. 7, weights 1/8).
  EvaluateOptions octuplet;
  octuplet.interpolation.cube_edge_m = 0.05;
  const EvaluateResult o = evaluate(r.model, targets, octuplet);
  const Eigen::Vector3d eps_mean =
      (r.model.corrections_sensor_m.col(0) + r.model.corrections_sensor_m.col(1) +
       r.model.corrections_sensor_m.col(5) + r.model.corrections_sensor_m.col(6) +
       r.model.corrections_sensor_m.col(25) + r.model.corrections_sensor_m.col(26) +
       r.model.corrections_sensor_m.col(30) + r.model.corrections_sensor_m.col(31)) /
      8.0;
  EXPECT_EIGEN_NEAR(o.correction.corrections_sensor_m.col(0), eps_mean, 1e-15);
}

TEST_F(FrontDoor, CorrectedFiducialsLandOnTheirRobotPositions) {
  const RegisterResult r =
      register_fiducials(fiducials);  // Eq. 6 then Eq. 8: R (X + eps) + tau = Y
  EXPECT_EIGEN_NEAR(
      r.model.T_robot_sensor.apply_all(fiducials.sensor_m + r.model.corrections_sensor_m),
      fiducials.robot_m, 1e-12);
}

TEST_F(FrontDoor, TheCallersInterpolationWinsOverTheModels) {
  RegisterOptions options;
  options.interpolation.method = InterpolationMethod::kOctuplet;
  options.interpolation.cube_edge_m = 0.05;
  const RegisterResult r = register_fiducials(fiducials, options);
  EXPECT_EQ(evaluate(r.model, targets).correction.method_used, InterpolationMethod::kOctuplet);
  EvaluateOptions scattered;
  scattered.interpolation.method = InterpolationMethod::kScattered;
  EXPECT_EQ(evaluate(r.model, targets, scattered).correction.method_used,
            InterpolationMethod::kScattered);
  const RegisterResult plain = register_fiducials(fiducials);
  EvaluateOptions cube_only;  // a cube edge alone selects octuplet
  cube_only.interpolation.cube_edge_m = 0.05;
  const EvaluateResult e = evaluate(plain.model, targets, cube_only);
  EXPECT_EQ(e.correction.method_used, InterpolationMethod::kOctuplet);
  EXPECT_EQ(e.interpolation.cube_edge_m, 0.05);
}

TEST_F(FrontDoor, NoiseFromRepeatsAndTheRepeatabilityKeptInTheModel) {
  fiducials.n_readings = Eigen::VectorXi::Constant(125, 4);
  fiducials.sensor_sq_dev_m2 = Points3::Constant(3, 125, 3 * 0.05e-3 * 0.05e-3);  // 0.05 mm
  RegisterOptions options;
  options.sigma_rep_m = 0.1e-3;
  const RegisterResult r = register_fiducials(fiducials, options);
  ASSERT_TRUE(r.noise.sigma_opt_m && r.noise.sigma_noise_m && r.noise.rho);
  EXPECT_NEAR(*r.noise.sigma_opt_m, 0.05e-3, 1e-15);
  EXPECT_NEAR(*r.noise.sigma_noise_m, std::hypot(0.05e-3, 0.1e-3), 1e-15);  // Eq. 9
  EXPECT_NEAR(*r.noise.rho, r.rigid_body.sigma_l_m / *r.noise.sigma_noise_m, 1e-12);
  EXPECT_FALSE(r.noise.rho_is_upper_bound());
  EXPECT_EQ(r.model.sigma_rep_m, 0.1e-3);
}

TEST_F(FrontDoor, AZeroWeightLeavesAFiducialOutOfTheFit) {
  fiducials.sensor_m.col(12) += Eigen::Vector3d(0.01, 0, 0);  // 10 mm off
  fiducials.weights = Eigen::VectorXd::Ones(125);
  fiducials.weights(12) = 0.0;
  const RegisterResult weighted = register_fiducials(fiducials);
  MeasuredPoints without;
  without.sensor_m.resize(3, 124);
  without.robot_m.resize(3, 124);
  for (Eigen::Index j = 0, k = 0; j < 125; ++j) {
    if (j == 12) continue;
    without.sensor_m.col(k) = fiducials.sensor_m.col(j);
    without.robot_m.col(k++) = fiducials.robot_m.col(j);
  }
  const RegisterResult reference = register_fiducials(without);
  EXPECT_EIGEN_NEAR(weighted.model.T_robot_sensor.rotation, reference.model.T_robot_sensor.rotation,
                    1e-12);
  EXPECT_EIGEN_NEAR(weighted.model.T_robot_sensor.translation_m,
                    reference.model.T_robot_sensor.translation_m, 1e-12);
}

TEST_F(FrontDoor, RobustNamesASwappedMarker) {
  fiducials.names.clear();
  for (int j = 0; j < 125; ++j) fiducials.names.push_back("F" + std::to_string(j));
  fiducials.sensor_m.col(3).swap(fiducials.sensor_m.col(80));
  RegisterOptions options;
  options.robust = OutlierOptions{};
  const RegisterResult r = register_fiducials(fiducials, options);
  EXPECT_EQ(r.rejected, (std::vector<std::string>{"F3", "F80"}));
  // Both keep their place with their neighbours' correction: the 5^3 grid stays complete.
  EXPECT_EQ(r.n_registered, 123u);
  EXPECT_EQ(r.model.fiducials.size(), 125u);
  ASSERT_TRUE(r.robust);
  ASSERT_EQ(r.robust->rejected.size(), 2u);
  for (const RejectedFiducial& f : r.robust->rejected) {
    EXPECT_TRUE(f.filled);
    EXPECT_GT(f.deviation_m, 0.05);  // the swapped markers lie more than 50 mm apart
    EXPECT_GT(f.sigmas, r.robust->detection.threshold_sigmas);
  }
  // The filled fiducials' corrections agree with Eq. 6 for the sensor reading stored with them.
  const Points3 eps = fiducial_corrections(r.model.T_robot_sensor,
                                           Points3(r.model.fiducials[3].sensor_m),
                                           Points3(r.model.fiducials[3].robot_m));
  EXPECT_EIGEN_NEAR(eps.col(0), Eigen::Vector3d(r.model.corrections_sensor_m.col(3)), 1e-12);
}

TEST_F(FrontDoor, ScaleMakesASimilarityThatIsNotRigid) {
  fiducials.sensor_m = 1.001 * T_sensor_robot.apply_all(fiducials.robot_m);  // no robot error
  RegisterOptions options;
  options.registration.estimate_scale = true;
  const RegisterResult r = register_fiducials(fiducials, options);
  EXPECT_NEAR(r.model.T_robot_sensor.scale, 1.0 / 1.001, 1e-12);
  EXPECT_THROW((void)r.model.T_robot_sensor.rigid(), InputError);
  EXPECT_NO_THROW((void)register_fiducials(targets).model.T_robot_sensor.rigid());
}

/// Runs `call` and returns the InputError's message ("" when nothing was thrown).
template <typename F>
std::string error_of(F call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(FrontDoor, BadInputIsAnInputErrorThatSaysWhat) {
  MeasuredPoints bad = fiducials;
  bad.robot_m = fiducials.robot_m.leftCols(124);
  EXPECT_THAT(error_of([&] { (void)register_fiducials(bad); }),
              HasSubstr("robot_m has 124 columns for 125"));
  bad = fiducials;
  bad.sensor_m(1, 9) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(error_of([&] { (void)register_fiducials(bad); }),
              HasSubstr("sensor_m is not all finite"));
  bad = fiducials;
  bad.names = {"a", "b"};
  EXPECT_THAT(error_of([&] { (void)register_fiducials(bad); }), HasSubstr("names has 2 entries"));
  bad = fiducials;
  bad.weights = Eigen::VectorXd::Constant(125, -1.0);
  EXPECT_THAT(error_of([&] { (void)register_fiducials(bad); }), HasSubstr("weights"));
  MeasuredPoints two;
  two.sensor_m = fiducials.sensor_m.leftCols(2);
  two.robot_m = fiducials.robot_m.leftCols(2);
  EXPECT_THAT(error_of([&] { (void)register_fiducials(two); }), HasSubstr("3"));
  MeasuredPoints line;
  line.robot_m = Points3(3, 5);
  for (int j = 0; j < 5; ++j) line.robot_m.col(j) = Eigen::Vector3d(0.1 * j, 0.0, 0.0);
  line.sensor_m = line.robot_m;
  EXPECT_THAT(error_of([&] { (void)register_fiducials(line); }), HasSubstr("collinear"));
  EXPECT_THAT(error_of([&] { (void)register_fiducials(MeasuredPoints{}); }),
              HasSubstr("no points"));

  RegisterOptions octuplet;
  octuplet.interpolation.method = InterpolationMethod::kOctuplet;
  EXPECT_THAT(error_of([&] { (void)register_fiducials(fiducials, octuplet); }),
              HasSubstr("cube edge"));
  RegisterOptions strategy1;
  strategy1.procedure2.strategy = planning::Strategy::kAsListed;
  EXPECT_THAT(error_of([&] { (void)register_fiducials(fiducials, strategy1); }),
              HasSubstr("one configuration"));
  RegisterOptions strategy3;
  strategy3.procedure2.strategy = planning::Strategy::kVolumeCorners;
  EXPECT_THAT(error_of([&] { (void)register_fiducials(fiducials, strategy3); }),
              HasSubstr("config column"));

  const RegisterResult r = register_fiducials(fiducials);
  MeasuredPoints unknown_robot = targets;
  unknown_robot.robot_m.resize(3, 0);
  EXPECT_THAT(error_of([&] { (void)evaluate(r.model, unknown_robot); }),
              HasSubstr("robot_m has 0"));
  CorrectOptions octuplet_choice;
  octuplet_choice.interpolation.method = InterpolationMethod::kOctuplet;
  octuplet_choice.interpolation.cube_edge_m = 0.05;
  EXPECT_THAT(error_of([&] { (void)correct(r.model, unknown_robot, octuplet_choice); }),
              HasSubstr("nominal robot position"));
  RegistrationModel empty;
  EXPECT_THAT(error_of([&] { (void)correct(empty, targets); }), HasSubstr("no fiducials"));
}

}  // namespace
}  // namespace vrreg
