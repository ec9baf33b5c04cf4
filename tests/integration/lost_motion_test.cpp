// SPDX-License-Identifier: Apache-2.0
// The lost-motion stage on a simulated UR5 with lost motion (smooth DH errors, repeatability and
// tracker noise, no transmission error): fitted beside a quadratic trend on the fiducials'
// deviations, then kriging of what it leaves; the targets (not fitted) reach the noise floor,
// kriging alone does not; on the same cell without lost motion the stage changes nothing.
#include "correction/lost_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "half_a1_cell.hpp"
#include "vrreg/correction/kriging.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/registration/rigid.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/vrreg.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace lost_motion_stage_test {

constexpr double kArcmin = M_PI / (180.0 * 60.0);

struct Cell {
  Points3 robot_m;        // commanded positions
  Points3 deviation_m;    // registered sensor reading minus command, robot frame
  Eigen::MatrixXd q_rad;  // commanded joints
  Eigen::MatrixXd sign;   // approach directions from the row (visit) order
};

struct Split {
  Cell fiducials, targets;
};

// The half of A1 with lost motion `lost_motion_rad` (half_a1_cell.hpp), split into its fiducials
// and targets.
Split simulate_cell(const std::vector<double>& lost_motion_rad) {
  const MeasurementSet kept = testing::half_a1_cell(lost_motion_rad);
  const std::vector<std::size_t> fiducials = kept.select(Role::kFiducial);
  const RegistrationResult registration =
      register_rigid(kept.sensor_points(fiducials), kept.robot_points(fiducials));
  Split out;
  for (const Role role : {Role::kFiducial, Role::kTarget}) {
    const std::vector<std::size_t> idx = kept.select(role);
    Cell& c = role == Role::kFiducial ? out.fiducials : out.targets;
    const auto n = static_cast<Eigen::Index>(idx.size());
    c.robot_m = kept.robot_points(idx);
    c.deviation_m = registration.T_robot_sensor.apply_all(kept.sensor_points(idx)) - c.robot_m;
    c.q_rad.resize(6, n);
    c.sign.resize(6, n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Location& loc = kept.locations[idx[static_cast<std::size_t>(i)]];
      c.q_rad.col(i) = Eigen::Map<const Eigen::VectorXd>(loc.q_rad.data(), 6);
      c.sign.col(i) = Eigen::Map<const Eigen::VectorXd>(loc.approach_sign.data(), 6);
    }
  }
  return out;
}

struct Outcome {
  double without_m = 0.0;  // RMS TRE at the targets, kriging alone
  double with_m = 0.0;     // lost-motion stage, then kriging of what it leaves
  detail::LostMotionFit fit;
};

double rms_3d(const Points3& e) { return std::sqrt(e.colwise().squaredNorm().mean()); }

Outcome correct_targets(const Split& cell) {
  const kinematics::SerialChain chain = simulation::ur5_testbed().nominal;
  KrigingOptions k;
  k.noise_sd_m = 0.05e-3;
  k.fit_subset = 300;  // hyperparameters from 300 of the fiducials keep the test short
  const Cell& f = cell.fiducials;
  const Cell& t = cell.targets;
  Outcome out;
  const KrigingModel plain = KrigingModel::fit(f.robot_m, f.deviation_m, k);
  out.without_m = rms_3d(t.deviation_m - plain.predict(t.robot_m).mean_m);
  out.fit = detail::fit_lost_motion(chain, f.q_rad, f.sign, f.robot_m, f.deviation_m, 2);
  const Points3 left_m =
      f.deviation_m - detail::lost_motion_deviation_m(chain, f.q_rad, f.sign, out.fit.beta_rad);
  const KrigingModel staged = KrigingModel::fit(f.robot_m, left_m, k);
  const Points3 predicted_m =
      detail::lost_motion_deviation_m(chain, t.q_rad, t.sign, out.fit.beta_rad) +
      staged.predict(t.robot_m).mean_m;
  out.with_m = rms_3d(t.deviation_m - predicted_m);
  return out;
}

TEST(LostMotionStage, ReachesTheNoiseFloorWhereKrigingAloneDoesNot) {
  if (vrreg::testing::sanitized()) GTEST_SKIP();
  // Noise floor sqrt(3 (sigma_rep^2 + sigma_opt^2 / K)) of the UR5 test bed: 0.05 mm per axis
  // per visit, 0.058 mm per reading, K = 12.
  const double floor_m = std::sqrt(3.0 * (0.05e-3 * 0.05e-3 + 0.058e-3 * 0.058e-3 / 12.0));
  const std::vector<double> lost_motion_rad = {0.8 * kArcmin, 0.2 * kArcmin, 0.15 * kArcmin,
                                               0.7 * kArcmin, 0.6 * kArcmin, 0.4 * kArcmin};
  const Outcome backlash = correct_targets(simulate_cell(lost_motion_rad));
  const Outcome none = correct_targets(simulate_cell({}));
  std::printf("lost motion cell: kriging %.4f mm (%.2fx floor), stage + kriging %.4f mm (%.2fx)\n",
              1e3 * backlash.without_m, backlash.without_m / floor_m, 1e3 * backlash.with_m,
              backlash.with_m / floor_m);
  std::printf("cell without:     kriging %.4f mm (%.2fx floor), stage + kriging %.4f mm (%.2fx)\n",
              1e3 * none.without_m, none.without_m / floor_m, 1e3 * none.with_m,
              none.with_m / floor_m);
  for (int j = 0; j < 6; ++j) {
    const double sd = std::sqrt(backlash.fit.covariance_rad2(j, j));
    std::printf("  joint %d: lost motion %.3f arcmin (sd %.3f), simulated %.3f; without: %.3f\n",
                j + 1, backlash.fit.beta_rad(j) / kArcmin, sd / kArcmin,
                lost_motion_rad[static_cast<std::size_t>(j)] / kArcmin,
                none.fit.beta_rad(j) / kArcmin);
  }
  EXPECT_GT(backlash.without_m, 1.12 * floor_m);  // measured 1.17x
  // Joint 1 (the largest effect) is recovered; the smaller ones share their signal with the
  // quadratic trend and come out biased by up to ~2 sd (docs/joint-space-model.md).
  EXPECT_NEAR(backlash.fit.beta_rad(0), lost_motion_rad[0],
              3.0 * std::sqrt(backlash.fit.covariance_rad2(0, 0)));
  EXPECT_LE(backlash.with_m, 1.10 * floor_m);
  EXPECT_LE(none.with_m, 1.01 * none.without_m);
}

}  // namespace lost_motion_stage_test
}  // namespace vrreg
