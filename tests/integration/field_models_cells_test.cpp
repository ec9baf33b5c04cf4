// The field models (issue 12) through the front door on the simulated A1 cell: register with the
// robot, evaluate with each model; the corrections beat the paper's octuplet RRBC by the margins
// measured with the scientific-Python peers, `auto` picks the joint-space model on a cell built
// from joint errors, and the predicted uncertainties are calibrated.
#include <gtest/gtest.h>

#include <cstdio>

#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/vrreg.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

class FieldModelsOnA1 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const simulation::Testbed ur5 = simulation::ur5_testbed();
    simulation::SimulationOptions o;
    o.seed = 1;
    set_ = new MeasurementSet(experiments::to_measurement_set(
        simulation::simulate_dataset(ur5, simulation::Dataset::kA1, o)));
    RegisterOptions options;
    options.sigma_rep_m = 1e-4;
    options.robot = ur5.nominal;
    model_ = new RegistrationModel(register_fiducials(*set_, options).model);
  }
  static void TearDownTestSuite() {
    delete set_;
    delete model_;
  }
  static EvaluateResult run(InterpolationMethod method, double cube_edge_m = 0.0) {
    EvaluateOptions options;
    options.interpolation.method = method;
    if (cube_edge_m > 0.0) options.interpolation.cube_edge_m = cube_edge_m;
    EvaluateResult r = evaluate(*model_, *set_, options);
    std::printf("A1 seed 1, %-9s cor RMS_T %.4f mm, calibration %.2f (%lld targets)\n",
                to_string(r.correction.method_used), 1e3 * r.summary.cor_rms_t_m,
                r.calibration.rms_ratio, static_cast<long long>(r.calibration.n));
    return r;
  }
  static MeasurementSet* set_;
  static RegistrationModel* model_;
};
MeasurementSet* FieldModelsOnA1::set_ = nullptr;
RegistrationModel* FieldModelsOnA1::model_ = nullptr;

TEST_F(FieldModelsOnA1, JointAndTrilinearBeatOctupletWithCalibratedSd) {
  const double octuplet_m = run(InterpolationMethod::kOctuplet, 0.05).summary.cor_rms_t_m;
  EXPECT_NEAR(octuplet_m, 0.239e-3, 0.01e-3);  // the reference (scipy on the same data)
  const EvaluateResult trilinear = run(InterpolationMethod::kTrilinear);
  EXPECT_LT(trilinear.summary.cor_rms_t_m, 0.70 * octuplet_m);
  EXPECT_EQ(trilinear.correction.n_flagged, 0);
  const EvaluateResult joint = run(InterpolationMethod::kJoint);
  EXPECT_LT(joint.summary.cor_rms_t_m, 0.100e-3);
  EXPECT_EQ(joint.calibration.n, 120);
  EXPECT_GT(joint.calibration.rms_ratio, 0.8);
  EXPECT_LT(joint.calibration.rms_ratio, 1.25);
  EXPECT_GT(joint.calibration.within_2sigma, 0.9);
}

TEST_F(FieldModelsOnA1, KrigingAndAutoBeatOctuplet) {
  if (testing::sanitized()) GTEST_SKIP() << "kriging's hyperparameter search is slow under ASan";
  const EvaluateResult kriging = run(InterpolationMethod::kKriging);
  EXPECT_LT(kriging.summary.cor_rms_t_m, 0.65 * 0.239e-3);
  EXPECT_GT(kriging.calibration.rms_ratio, 0.6);
  EXPECT_LT(kriging.calibration.rms_ratio, 1.25);
  const EvaluateResult automatic = run(InterpolationMethod::kAuto);
  ASSERT_TRUE(automatic.cross_validation);
  EXPECT_EQ(automatic.cross_validation->chosen, InterpolationMethod::kJoint);
  EXPECT_EQ(automatic.correction.method_used, InterpolationMethod::kJoint);
  EXPECT_EQ(automatic.cross_validation->rows.size(), 5U);
}

// Every second node (50 mm, 210 fiducials): joint 1's 4 deg transmission error is sampled at 42
// azimuths only, none of them a target's. A Legendre series is free between them (0.16 mm
// here); the periodic term finds the period and carries the wave to the targets (0.10 mm).
TEST_F(FieldModelsOnA1, ThinnedGridJointModelFindsTheTransmissionPeriod) {
  MeasurementSet thinned = *set_;
  thinned.locations.clear();
  for (const Location& loc : set_->locations) {
    int i = 0, j = 0, k = 0;
    ASSERT_EQ(std::sscanf(loc.point.c_str(), "p%d_%d_%d", &i, &j, &k), 3) << loc.point;
    if (loc.role == Role::kTarget || (i % 2 == 0 && j % 2 == 0 && k % 2 == 0))
      thinned.locations.push_back(loc);
  }
  RegisterOptions options;
  options.sigma_rep_m = 1e-4;
  options.robot = simulation::ur5_testbed().nominal;
  const RegistrationModel model = register_fiducials(thinned, options).model;
  EvaluateOptions eval;
  eval.interpolation.method = InterpolationMethod::kOctuplet;
  eval.interpolation.cube_edge_m = 0.05;
  const double octuplet_m = evaluate(model, thinned, eval).summary.cor_rms_t_m;
  eval.interpolation.method = InterpolationMethod::kJoint;
  const EvaluateResult joint = evaluate(model, thinned, eval);
  std::printf("A1 seed 1 thinned: octuplet %.4f mm, joint %.4f mm, calibration %.2f\n",
              1e3 * octuplet_m, 1e3 * joint.summary.cor_rms_t_m, joint.calibration.rms_ratio);
  EXPECT_LT(joint.summary.cor_rms_t_m, 0.70 * octuplet_m);  // the "30 % below"
  EXPECT_GT(joint.calibration.rms_ratio, 0.8);
  EXPECT_LT(joint.calibration.rms_ratio, 1.25);
  EXPECT_NE(joint.correction.layout.find("joint 1 4.0"), std::string::npos)
      << joint.correction.layout;
}

// A robot whose kinematics the fiducials' nominal positions are not is refused, not fitted.
TEST_F(FieldModelsOnA1, WrongRobotIsRefused) {
  EvaluateOptions options;
  options.interpolation.method = InterpolationMethod::kJoint;
  options.robot = kinematics::ur10();
  EXPECT_THROW((void)evaluate(*model_, *set_, options), InputError);
}

}  // namespace
}  // namespace vrreg
