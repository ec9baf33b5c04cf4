// SPDX-License-Identifier: Apache-2.0
// Orientations through the front door's arrays (MeasuredPoints::q_sensor_marker, q_robot_marker)
// and the prepared corrector: the same corrected orientations, bit for bit, as the measurement
// set's way; a sensor moved since registration (a bump) rotates today's orientations back; an
// orientation the model cannot correct is an error, never a silent position-only answer.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "orientation_cell.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/pipeline/prepared_corrector.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg {
namespace {

using testing::cell_with_orientations;
using testing::points_of;

RegistrationModel registered(const MeasurementSet& set, InterpolationMethod method) {
  RegisterOptions options;
  options.interpolation.method = method;
  return register_fiducials(set, options).model;
}

void expect_same(const OrientationCorrection& a, const OrientationCorrection& b) {
  ASSERT_EQ(a.corrected_R_robot_marker.size(), b.corrected_R_robot_marker.size());
  for (std::size_t t = 0; t < a.corrected_R_robot_marker.size(); ++t) {
    EXPECT_EQ(a.corrected_R_robot_marker[t], b.corrected_R_robot_marker[t]) << t;
    EXPECT_EQ(a.status[t], b.status[t]) << t;
  }
  EXPECT_EQ(a.corrections_robot_rad, b.corrections_robot_rad);
  ASSERT_EQ(a.predicted_sd_rad.size(), b.predicted_sd_rad.size());
  for (Eigen::Index t = 0; t < a.predicted_sd_rad.size(); ++t) {  // NaN where not corrected
    EXPECT_TRUE(a.predicted_sd_rad(t) == b.predicted_sd_rad(t) ||
                (std::isnan(a.predicted_sd_rad(t)) && std::isnan(b.predicted_sd_rad(t))))
        << t;
  }
}

TEST(OrientationArrays, CorrectOnArraysAndPreparedGiveTheSetsOrientations) {
  const MeasurementSet set = cell_with_orientations();
  const MeasuredPoints targets = points_of(set, Role::kTarget);
  for (const InterpolationMethod method :
       {InterpolationMethod::kScattered, InterpolationMethod::kTrilinear,
        InterpolationMethod::kKriging}) {
    SCOPED_TRACE(to_string(method));
    const RegistrationModel model = registered(set, method);
    const CorrectResult from_set = correct(model, set);
    const CorrectResult from_arrays = correct(model, targets);
    ASSERT_TRUE(from_set.orientation && from_arrays.orientation);
    EXPECT_EQ(from_arrays.correction.corrected_robot_m, from_set.correction.corrected_robot_m);
    expect_same(*from_arrays.orientation, *from_set.orientation);
    const PreparedCorrector prepared(std::make_shared<const RegistrationModel>(model), {});
    EXPECT_TRUE(prepared.corrects_orientation());
    EXPECT_EQ(prepared.predicts_angle_sd(), method != InterpolationMethod::kScattered);
    const CorrectResult once = prepared.correct(targets);
    ASSERT_TRUE(once.orientation);
    expect_same(*once.orientation, *from_set.orientation);
    // Corrected: the angle to the commanded orientation is a fraction of the uncorrected one.
    double unc2 = 0.0;
    double cor2 = 0.0;
    for (std::size_t t = 0; t < targets.q_robot_marker.size(); ++t) {
      const Eigen::Matrix3d commanded = targets.q_robot_marker[t].toRotationMatrix();
      unc2 += std::pow(
          rotation_angle_rad(once.orientation->uncorrected_R_robot_marker[t], commanded), 2);
      cor2 +=
          std::pow(rotation_angle_rad(once.orientation->corrected_R_robot_marker[t], commanded), 2);
    }
    EXPECT_LT(cor2, 0.1 * unc2);
  }
}

TEST(OrientationArrays, PositionsAreTheSameWithOrWithoutOrientations) {
  const MeasurementSet set = cell_with_orientations();
  const RegistrationModel model = registered(set, InterpolationMethod::kKriging);
  MeasuredPoints targets = points_of(set, Role::kTarget);
  const CorrectResult with = correct(model, targets);
  targets.q_sensor_marker.clear();
  targets.q_robot_marker.clear();
  const CorrectResult without = correct(model, targets);
  EXPECT_FALSE(without.orientation.has_value());
  EXPECT_EQ(with.correction.corrected_robot_m, without.correction.corrected_robot_m);
  EXPECT_EQ(with.correction.predicted_sd_m, without.correction.predicted_sd_m);
}

TEST(OrientationArrays, RegisterAndEvaluateOnArraysCarryOrientations) {
  const MeasurementSet set = cell_with_orientations();
  RegisterOptions options;
  options.interpolation.method = InterpolationMethod::kTrilinear;
  const RegistrationModel model =
      register_fiducials(points_of(set, Role::kFiducial), options).model;
  ASSERT_TRUE(model.orientation_corrector.has_value());
  const EvaluateResult e = evaluate(model, points_of(set, Role::kTarget));
  ASSERT_TRUE(e.orientation.has_value());
  EXPECT_LT(e.orientation->cor_rms_rad, 0.3 * e.orientation->unc_rms_rad);
}

TEST(OrientationArrays, ABumpedSensorsOrientationsAreTurnedBack) {
  const MeasurementSet set = cell_with_orientations();
  const RegistrationModel model = registered(set, InterpolationMethod::kTrilinear);
  const MeasuredPoints targets = points_of(set, Role::kTarget);
  // The sensor moved: today's readings are M^-1 of the registration's; the model knows M.
  const RigidTransform M(rotation_exp(Eigen::Vector3d(0.01, -0.02, 0.03)),
                         Eigen::Vector3d(0.002, -0.001, 0.003));
  RegistrationModel bumped = model;
  bumped.T_registered_sensor = M;
  MeasuredPoints today = targets;
  today.sensor_m = M.inverse().apply_all(targets.sensor_m);
  for (Eigen::Quaterniond& q : today.q_sensor_marker) {
    q = Eigen::Quaterniond(M.rotation.transpose()) * q;
  }
  const CorrectResult before = correct(model, targets);
  const CorrectResult after = correct(bumped, today);
  const PreparedCorrector prepared(std::make_shared<const RegistrationModel>(bumped), {});
  const CorrectResult after_prepared = prepared.correct(today);
  ASSERT_TRUE(before.orientation && after.orientation && after_prepared.orientation);
  for (std::size_t t = 0; t < targets.q_sensor_marker.size(); ++t) {
    EXPECT_LT(rotation_angle_rad(after.orientation->corrected_R_robot_marker[t],
                                 before.orientation->corrected_R_robot_marker[t]),
              1e-12);
    EXPECT_EQ(after_prepared.orientation->corrected_R_robot_marker[t],
              after.orientation->corrected_R_robot_marker[t]);
  }
  EXPECT_LT((after.correction.corrected_robot_m - before.correction.corrected_robot_m)
                .cwiseAbs()
                .maxCoeff(),
            1e-12);
}

TEST(OrientationArrays, OrientationsTheModelCannotCorrectAreRefused) {
  MeasurementSet positions_only = cell_with_orientations();
  for (Location& l : positions_only.locations) l.q_robot_marker.reset();
  const RegistrationModel model = registered(positions_only, InterpolationMethod::kScattered);
  EXPECT_FALSE(model.orientation_corrector.has_value());
  const MeasuredPoints targets = points_of(cell_with_orientations(), Role::kTarget);
  EXPECT_THROW((void)correct(model, targets), InputError);
  const PreparedCorrector prepared(std::make_shared<const RegistrationModel>(model), {});
  EXPECT_FALSE(prepared.corrects_orientation());
  EXPECT_THROW((void)prepared.correct(targets), InputError);

  const RegistrationModel with =
      registered(cell_with_orientations(), InterpolationMethod::kScattered);
  MeasuredPoints bad = targets;
  bad.q_sensor_marker[3].coeffs() *= 1.01;  // not a unit quaternion
  try {
    (void)correct(with, bad);
    FAIL() << "a quaternion of norm 1.01 was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("q_sensor_marker[3]"), std::string::npos) << e.what();
  }
  bad = targets;
  bad.q_sensor_marker.pop_back();
  EXPECT_THROW((void)correct(with, bad), InputError);
  bad = targets;
  bad.q_sensor_marker[0].coeffs()(1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)correct(with, bad), InputError);
}

}  // namespace
}  // namespace vrreg
