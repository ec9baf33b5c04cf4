// SPDX-License-Identifier: Apache-2.0
// The field models through the front door on the simulated A1 cell: register with the
// robot, evaluate with each model; the corrections beat the paper's octuplet RRBC by the margins
// measured with the scientific-Python peers, `auto` picks the joint-space model on a cell built
// from joint errors, and the predicted uncertainties are calibrated.
#include <gmock/gmock.h>
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
  // The rows of A1 whose grid node p<i>_<j>_<k> and role `keep` accepts.
  template <class Keep>
  static MeasurementSet nodes(Keep keep) {
    MeasurementSet out = *set_;
    out.locations.clear();
    for (const Location& loc : set_->locations) {
      Eigen::Vector3i n;
      EXPECT_EQ(std::sscanf(loc.point.c_str(), "p%d_%d_%d", &n.x(), &n.y(), &n.z()), 3)
          << loc.point;
      if (keep(n, loc.role)) out.locations.push_back(loc);
    }
    return out;
  }
  static RegistrationModel registered(const MeasurementSet& set) {
    RegisterOptions options;
    options.sigma_rep_m = 1e-4;
    options.robot = simulation::ur5_testbed().nominal;
    return register_fiducials(set, options).model;
  }
  static bool even(const Eigen::Vector3i& n) {
    return n.x() % 2 == 0 && n.y() % 2 == 0 && n.z() % 2 == 0;
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

// The adaptive loop's stop judged by the joint-space model (plan_next's correction_sd): at the
// targets, with their joints, the sd the model predicts is the one evaluate reports there; too
// few fiducials give no sd and the reason.
TEST_F(FieldModelsOnA1, CorrectionSdAtPartsIsTheModelsPredictedSd) {
  RegisterOptions options;
  options.sigma_rep_m = 1e-4;
  options.robot = simulation::ur5_testbed().nominal;
  options.interpolation.method = InterpolationMethod::kJoint;
  std::vector<planning::PartPlan> parts;
  for (const Location& loc : set_->locations) {
    if (loc.role != Role::kTarget) continue;
    planning::PartPlan& p = parts.emplace_back();
    p.name = loc.point;
    p.robot_m = loc.robot_m;
    p.q_rad = Eigen::Map<const Eigen::VectorXd>(loc.q_rad.data(), std::ssize(loc.q_rad));
    p.reachable = true;
  }
  ASSERT_EQ(parts.size(), 120U);
  const planning::CorrectionSd sd = correction_sd_at_parts(*set_, options)(parts);
  ASSERT_TRUE(sd.sd_m) << sd.note;
  EXPECT_EQ(sd.method, "joint");
  const EvaluateResult joint = run(InterpolationMethod::kJoint);
  ASSERT_EQ(joint.correction.predicted_sd_m.size(), 120);
  for (Eigen::Index i = 0; i < 120; ++i) {
    EXPECT_NEAR((*sd.sd_m)(i), joint.correction.predicted_sd_m(i),
                0.02 * joint.correction.predicted_sd_m(i))
        << parts[static_cast<std::size_t>(i)].name;
  }

  MeasurementSet few = nodes([](const Eigen::Vector3i& n, Role role) {
    const int d = (n - Eigen::Vector3i(4, 6, 4)).cwiseAbs().maxCoeff();
    return role == Role::kFiducial && even(n) && d <= 2;
  });
  const planning::CorrectionSd none = correction_sd_at_parts(few, options)(parts);
  EXPECT_FALSE(none.sd_m);
  EXPECT_THAT(none.note, ::testing::HasSubstr("equations per parameter"));
}

// Every second node (50 mm, 210 fiducials): joint 1's 4 deg transmission error is sampled at 42
// azimuths only, none of them a target's. A Legendre series is free between them (0.16 mm
// here); the periodic term finds the period and carries the wave to the targets (0.10 mm).
TEST_F(FieldModelsOnA1, ThinnedGridJointModelFindsTheTransmissionPeriod) {
  const MeasurementSet thinned =
      nodes([](const Eigen::Vector3i& n, Role role) { return role == Role::kTarget || even(n); });
  const RegistrationModel model = registered(thinned);
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

// The 27 even nodes (50 mm apart) around p04_06_04: the joint-space model would identify ~45
// parameters from 81 equations, and is refused with the count it needs, alone and in `auto`,
// which then picks another method.
TEST_F(FieldModelsOnA1, TwentySevenFiducialsAreTooFewForTheJointModel) {
  const MeasurementSet cube = nodes([](const Eigen::Vector3i& n, Role role) {
    const int d = (n - Eigen::Vector3i(4, 6, 4)).cwiseAbs().maxCoeff();
    return role == Role::kTarget ? d <= 1 : even(n) && d <= 2;
  });
  ASSERT_EQ(cube.select(Role::kFiducial).size(), 27U);
  ASSERT_EQ(cube.select(Role::kTarget).size(), 8U);
  const RegistrationModel model = registered(cube);
  EvaluateOptions eval;
  eval.interpolation.method = InterpolationMethod::kJoint;
  try {
    (void)evaluate(model, cube, eval);
    ADD_FAILURE() << "the joint model was fitted to 27 fiducials";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("from 27 fiducials (81 equations); it needs at "
                                               "least 3 equations per parameter"));
  }
  if (testing::sanitized()) return;  // kriging's hyperparameter search is slow under ASan
  eval.interpolation.method = InterpolationMethod::kAuto;
  const EvaluateResult automatic = evaluate(model, cube, eval);
  ASSERT_TRUE(automatic.cross_validation);
  EXPECT_NE(automatic.cross_validation->chosen, InterpolationMethod::kJoint);
  bool listed = false;
  for (const CrossValidationRow& row : automatic.cross_validation->rows) {
    if (row.method != InterpolationMethod::kJoint) continue;
    listed = true;
    EXPECT_FALSE(row.applicable);
    EXPECT_THAT(row.note, ::testing::HasSubstr("equations per parameter"));
  }
  EXPECT_TRUE(listed);
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
