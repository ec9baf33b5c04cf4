// SPDX-License-Identifier: Apache-2.0
// The lost-motion stage of the corrector against closed forms: deviations that are exactly the
// term -J diag(s) beta / 2 plus a quadratic field give back the plays (to round-off) with sd 0;
// with noise, the plays' spread over many draws matches their covariance; a query without
// approach directions gets the term's mean (none) and an sd wider by exactly |J_j beta_j| / 2
// per joint; auto leaves a cell without lost motion bit for bit as off does.
#include "correction/lost_motion_stage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/correction/corrector.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg {
namespace lost_motion_corrector_test {

constexpr double kArcmin = M_PI / (180.0 * 60.0);

Eigen::VectorXd true_plays() {
  Eigen::VectorXd play(6);
  play << 0.8, 0.2, 0.15, 0.7, 0.6, 0.4;
  return play * kArcmin;
}

struct Points {
  Eigen::MatrixXd q_rad, sign;
  Points3 robot_m;
};

// n commanded poses of a UR5 around an upright working pose, each joint arriving from a random
// side.
Points poses(int n, Random& rng) {
  const kinematics::SerialChain chain = kinematics::ur5();
  Eigen::VectorXd q0(6);
  q0 << 0.2, -1.3, 1.5, -1.8, -1.57, 0.3;
  Points p{Eigen::MatrixXd(6, n), Eigen::MatrixXd(6, n), Points3(3, n)};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < 6; ++j) {
      p.q_rad(j, i) = q0(j) + rng.uniform(-0.25, 0.25);
      p.sign(j, i) = rng.uniform() < 0.5 ? -1.0 : 1.0;
    }
    p.robot_m.col(i) = kinematics::forward_kinematics(chain, p.q_rad.col(i)).translation();
  }
  return p;
}

// A smooth (quadratic) field of about half a millimetre over the poses [m].
Eigen::Vector3d field_m(const Eigen::Vector3d& y) {
  const Eigen::Vector3d d = y - Eigen::Vector3d(0.1, 0.1, 0.4);
  return 1e-3 * Eigen::Vector3d(0.8 * d.x() + 2.0 * d.y() * d.z(),
                                -0.5 * d.z() + 1.5 * d.x() * d.x(),
                                0.3 + 0.6 * d.y() - 1.0 * d.x() * d.z());
}

SimilarityTransform registration() {
  SimilarityTransform T;
  T.rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  T.translation_m = Eigen::Vector3d(0.5, -0.2, 1.9);
  T.scale = 1.0002;  // the stage maps between frames through the scale too
  return T;
}

// The fiducials' data: reached = commanded + lost motion (plays `play`) + field + noise.
CorrectorData cell(const Points& p, const Eigen::VectorXd& play, double noise_sd_m, Random& rng) {
  const kinematics::SerialChain chain = kinematics::ur5();
  const SimilarityTransform T = registration();
  const SimilarityTransform T_sensor_robot = T.inverse();
  const Eigen::Index n = p.robot_m.cols();
  Points3 sensor_m(3, n);
  Points3 corrections_m(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Vector3d deviation = field_m(p.robot_m.col(i)) + rng.normal3(noise_sd_m);
    for (int j = 0; j < 6; ++j) {
      deviation -= 0.5 * p.sign(j, i) * play(j) *
                   kinematics::jacobian(chain, p.q_rad.col(i)).block<3, 1>(0, j);
    }
    sensor_m.col(i) = T_sensor_robot.apply(Eigen::Vector3d(p.robot_m.col(i) + deviation));
    corrections_m.col(i) =
        T_sensor_robot.apply(Eigen::Vector3d(p.robot_m.col(i))) - sensor_m.col(i);
  }
  CorrectorData data = CorrectorData::of(T, sensor_m, p.robot_m, corrections_m);
  data.joints_rad = p.q_rad;
  data.approach_sign = p.sign;
  data.robot = chain;
  return data;
}

// Equal bit for bit, NaN (a point without a prediction) equal to NaN.
bool same(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.array() == b.array() || (a.array().isNaN() && b.array().isNaN())).all();
}

// The UR5's marker (its flange centre) lies on joint 6's axis: joint 6's play moves no position,
// so it is not identified and comes out 0 with variance 0.
constexpr int kIdentified = 5;

CorrectorOptions rbf(LostMotionMode mode) {
  CorrectorOptions o;
  o.interpolation.method = InterpolationMethod::kRbf;
  o.lost_motion = mode;
  o.tabulate = false;
  return o;
}

TEST(LostMotionCorrector, RecoversExactPlaysWithZeroSdNoiseFree) {
  Random rng(11);
  const CorrectorData data = cell(poses(150, rng), true_plays(), 0.0, rng);
  const Corrector c = Corrector::fit(data, rbf(LostMotionMode::kOn));
  ASSERT_TRUE(c.lost_motion());
  const LostMotionTerm& term = *c.lost_motion();
  EXPECT_TRUE(term.applied);
  EXPECT_EQ(term.play_rad(5), 0.0);
  EXPECT_EQ(term.covariance_rad2(5, 5), 0.0);
  for (int j = 0; j < kIdentified; ++j) {
    EXPECT_NEAR(term.play_rad(j), true_plays()(j), 1e-9 * true_plays()(j)) << "joint " << j + 1;
    EXPECT_LE(std::sqrt(term.covariance_rad2(j, j)), 1e-9 * true_plays()(j)) << "joint " << j + 1;
  }
}

TEST(LostMotionCorrector, PlaysSpreadMatchesTheirCovariance) {
  // 40 poses, 0.05 mm noise per axis, 200 draws: the spread of each play over the draws against
  // the RMS of its predicted sd (each within 15 %; the spread's own sampling error is ~5 %).
  Random layout(3);
  const Points p = poses(40, layout);
  const int draws = 200;
  Eigen::MatrixXd plays(6, draws);
  Eigen::VectorXd predicted_var = Eigen::VectorXd::Zero(6);
  for (int d = 0; d < draws; ++d) {
    Random rng(100 + static_cast<std::uint64_t>(d));
    const CorrectorData data = cell(p, true_plays(), 0.05e-3, rng);
    const LostMotionTerm term =
        detail::fit_lost_motion_term(data, LostMotionMode::kOn, MethodSettings{}, 5, 1);
    plays.col(d) = term.play_rad;
    predicted_var += term.covariance_rad2.diagonal() / draws;
  }
  const Eigen::VectorXd mean = plays.rowwise().mean();
  for (int j = 0; j < kIdentified; ++j) {
    const double spread = std::sqrt((plays.row(j).array() - mean(j)).square().sum() / (draws - 1));
    const double predicted = std::sqrt(predicted_var(j));
    EXPECT_NEAR(spread / predicted, 1.0, 0.15) << "joint " << j + 1;
    EXPECT_NEAR(mean(j), true_plays()(j), 4.0 * predicted / std::sqrt(draws)) << "joint " << j + 1;
  }
}

TEST(LostMotionCorrector, QueryWithoutDirectionsTakesTheMeanAndAWiderSd) {
  Random rng(12);
  const CorrectorData data = cell(poses(150, rng), true_plays(), 0.0, rng);
  const Corrector c = Corrector::fit(data, rbf(LostMotionMode::kOn));
  Random query_rng(13);
  const Points t = poses(20, query_rng);
  const Points3 sensor_m = registration().inverse().apply_all(t.robot_m);
  const Points3 none(3, 0);
  const CorrectionQuery with(sensor_m, none, t.q_rad, {}, t.sign);
  const CorrectionQuery without(sensor_m, none, t.q_rad);
  const TargetCorrection a = c.correct(with);
  const TargetCorrection b = c.correct(without);
  const kinematics::SerialChain chain = kinematics::ur5();
  const SimilarityTransform T = registration();
  for (Eigen::Index i = 0; i < t.q_rad.cols(); ++i) {
    ASSERT_EQ(a.stencils[static_cast<std::size_t>(i)].status, StencilStatus::kOk);
    const kinematics::Jacobian jac = kinematics::jacobian(chain, t.q_rad.col(i));
    Eigen::Vector3d deviation = Eigen::Vector3d::Zero();
    double spread_m2 = 0.0;
    for (int j = 0; j < 6; ++j) {
      const Eigen::Vector3d column = 0.5 * true_plays()(j) * jac.block<3, 1>(0, j);
      deviation -= t.sign(j, i) * column;
      spread_m2 += column.squaredNorm();
    }
    // The term's correction is minus the deviation, in the sensor frame.
    const Eigen::Vector3d term_sensor = -T.rotation.transpose() * deviation / T.scale;
    EXPECT_LE((a.corrections_sensor_m.col(i) - b.corrections_sensor_m.col(i) - term_sensor).norm(),
              1e-12);
    EXPECT_NEAR(
        b.predicted_sd_m(i) * b.predicted_sd_m(i) - a.predicted_sd_m(i) * a.predicted_sd_m(i),
        spread_m2, 1e-9 * spread_m2);
  }
}

TEST(LostMotionCorrector, AutoLeavesACellWithoutLostMotionAsOffDoes) {
  Random rng(14);
  const CorrectorData data = cell(poses(200, rng), Eigen::VectorXd::Zero(6), 0.03e-3, rng);
  const Corrector automatic = Corrector::fit(data, rbf(LostMotionMode::kAuto));
  const Corrector off = Corrector::fit(data, rbf(LostMotionMode::kOff));
  ASSERT_TRUE(automatic.lost_motion());
  EXPECT_FALSE(automatic.lost_motion()->applied) << automatic.lost_motion()->reason;
  EXPECT_GT(automatic.lost_motion()->n_compared, 150);
  EXPECT_FALSE(off.lost_motion());
  Random query_rng(15);
  const Points t = poses(30, query_rng);
  const Points3 sensor_m = registration().inverse().apply_all(t.robot_m);
  const TargetCorrection a = automatic.correct(CorrectionQuery(sensor_m));
  const TargetCorrection b = off.correct(CorrectionQuery(sensor_m));
  EXPECT_TRUE(same(a.corrected_robot_m, b.corrected_robot_m));
  EXPECT_TRUE(same(a.predicted_sd_m, b.predicted_sd_m));
}

TEST(LostMotionCorrector, AutoEntersWithLostMotionAndBeatsTheMethodAlone) {
  Random rng(16);
  const CorrectorData data = cell(poses(200, rng), true_plays(), 0.03e-3, rng);
  const Corrector c = Corrector::fit(data, rbf(LostMotionMode::kAuto));
  ASSERT_TRUE(c.lost_motion());
  const LostMotionTerm& term = *c.lost_motion();
  EXPECT_TRUE(term.applied) << term.reason;
  EXPECT_EQ(term.judged_by, InterpolationMethod::kRbf);
  EXPECT_LT(term.cv_rms_with_m, 0.95 * term.cv_rms_without_m);
}

TEST(LostMotionCorrector, SavedAndRestoredCorrectsWithTheSameBits) {
  Random rng(17);
  const CorrectorData data = cell(poses(150, rng), true_plays(), 0.03e-3, rng);
  CorrectorOptions options = rbf(LostMotionMode::kOn);
  options.tabulate = true;
  const Corrector c = Corrector::fit(data, options);
  const Corrector restored = Corrector::restore(c.save(), data);
  ASSERT_TRUE(restored.lost_motion());
  EXPECT_TRUE(restored.lost_motion()->play_rad == c.lost_motion()->play_rad);
  Random query_rng(18);
  const Points t = poses(30, query_rng);
  const Points3 sensor_m = registration().inverse().apply_all(t.robot_m);
  const Points3 none(3, 0);
  const CorrectionQuery q(sensor_m, none, t.q_rad, {}, t.sign);
  EXPECT_TRUE(same(c.correct(q).corrected_robot_m, restored.correct(q).corrected_robot_m));
  EXPECT_TRUE(same(c.correct(q).predicted_sd_m, restored.correct(q).predicted_sd_m));
}

TEST(LostMotionCorrector, RefusesWhatItCannotFitOrAnswer) {
  Random rng(19);
  CorrectorData data = cell(poses(60, rng), true_plays(), 0.0, rng);
  const Corrector c = Corrector::fit(data, rbf(LostMotionMode::kOn));
  // Asked without joints: the term cannot be evaluated.
  try {
    (void)c.correct(CorrectionQuery(data.registered_robot_m));
    ADD_FAILURE() << "a query without joints was answered";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give the joints"), std::string::npos) << e.what();
  }
  // Forced on where every joint arrived from one side.
  data.approach_sign.setOnes();
  EXPECT_THROW((void)Corrector::fit(data, rbf(LostMotionMode::kOn)), InputError);
  const Corrector automatic = Corrector::fit(data, rbf(LostMotionMode::kAuto));
  EXPECT_FALSE(automatic.lost_motion());
}

}  // namespace lost_motion_corrector_test
}  // namespace vrreg
