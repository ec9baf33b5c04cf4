// SPDX-License-Identifier: Apache-2.0
// ISO 9283 multi-directional accuracy on a simulated UR5 with lost motion: every target visited
// once from above and once from below (a via point before each, all joints one way), noise-free
// robot and tracker; the uncorrected spread between the two directions' positions is the closed
// form |J_pos(q) b take_up| (the joints stop take_up b / 2 short of their command against the
// direction they came from), and a model fitted without directions cannot remove it.
#include "vrreg/metrics/multidirectional.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/vrreg.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace multidirectional_test {

constexpr double kArcmin = M_PI / (180.0 * 60.0);

TEST(MultidirectionalAccuracy, UncorrectedSpreadIsTheLostMotionsClosedForm) {
  const simulation::Testbed ur5 = simulation::ur5_testbed();
  const std::vector<double> play_rad = {0.8 * kArcmin, 0.2 * kArcmin, 0.15 * kArcmin,
                                        0.7 * kArcmin, 0.6 * kArcmin, 0.4 * kArcmin};
  const double take_up = 0.8;
  simulation::SimulationOptions o;
  o.seed = 3;
  o.errors = ur5.default_errors;
  o.errors->robot.transmission_amplitude_rad.clear();
  o.errors->robot.transmission_period_rad.clear();
  o.errors->robot.repeatability_sigma_m = 0.0;
  o.errors->robot.lost_motion_rad = play_rad;
  o.errors->robot.lost_motion_take_up = take_up;
  o.errors->tracker.noise_sigma_m.setZero();
  o.errors->tracker.readings_per_location = 1;
  // Fiducials on a 4 x 4 x 3 joint-space lattice about the home posture, all approached from
  // below; 12 targets between them, each visited from below (name t<k>) and from above (u<k>).
  std::vector<simulation::CommandedLocation> plan;
  const kinematics::JointVector home = ur5.home_q_rad;
  const auto location = [&](const std::string& name, Role role, const Eigen::VectorXd& dq,
                            double via_rad) {
    simulation::CommandedLocation l;
    l.point = name;
    l.role = role;
    l.q_rad = home + dq;
    l.robot_m = kinematics::forward_kinematics(ur5.nominal, l.q_rad).translation();
    l.via_q_rad = kinematics::JointVector(l.q_rad - Eigen::VectorXd::Constant(6, via_rad));
    return l;
  };
  int k = 0;
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      for (int c = 0; c < 3; ++c, ++k) {
        Eigen::VectorXd dq(6);
        dq << 0.06 * (a - 1.5), 0.05 * (b - 1.5), 0.06 * (c - 1), 0.1 * (a - b), 0.05 * c, 0.02 * b;
        plan.push_back(location("f" + std::to_string(k), Role::kFiducial, dq, 0.02));
      }
    }
  }
  std::vector<Eigen::VectorXd> target_dq;
  for (int t = 0; t < 12; ++t) {
    Eigen::VectorXd dq(6);
    dq << 0.06 * ((t % 3) - 1) + 0.03, 0.05 * ((t / 3) % 2) - 0.025, 0.03, 0.1 * ((t % 4) - 1.5),
        0.05, 0.02 * (t % 2);
    target_dq.push_back(dq);
    plan.push_back(location("t" + std::to_string(t), Role::kTarget, dq, 0.02));   // from below
    plan.push_back(location("u" + std::to_string(t), Role::kTarget, dq, -0.02));  // from above
  }
  const MeasurementSet set =
      experiments::to_measurement_set(simulation::simulate_plan(ur5, plan, o));
  const std::vector<std::size_t> fiducial_rows = set.select(Role::kFiducial);
  MeasuredPoints fiducials;
  fiducials.sensor_m = set.sensor_points(fiducial_rows);
  fiducials.robot_m = set.robot_points(fiducial_rows);
  RegisterOptions options;
  options.interpolation.method = InterpolationMethod::kKriging;
  const RegisterResult model = register_fiducials(fiducials, options);
  EvaluateOptions evaluate_options;
  evaluate_options.extrapolate = true;
  const EvaluateResult r = evaluate(model.model, set, evaluate_options);
  const std::vector<std::size_t> target_rows = set.select(Role::kTarget);
  ASSERT_EQ(static_cast<std::size_t>(r.n_targets()), target_rows.size());
  std::vector<std::vector<double>> signs;
  for (const std::size_t i : target_rows) signs.push_back(set.locations[i].approach_sign);
  EXPECT_EQ(approach_text(signs[0]), "++++++");
  EXPECT_EQ(approach_text(signs[1]), "------");
  const MultidirectionalAccuracy m =
      multidirectional_accuracy(r.targets_robot_m, r.correction.uncorrected_robot_m,
                                r.correction.corrected_robot_m, signs, {});  // by position
  ASSERT_EQ(m.n_points, 12);
  ASSERT_EQ(m.directions.size(), 2u);
  const Eigen::Map<const Eigen::VectorXd> play(play_rad.data(), 6);
  double worst_relative = 0.0;
  for (int t = 0; t < 12; ++t) {
    const kinematics::Jacobian J = kinematics::jacobian(ur5.nominal, home + target_dq[t]);
    const double closed_form_m = (J.topRows<3>() * (take_up * play)).norm();
    worst_relative = std::max(worst_relative, std::abs(m.unc_spread_m(t) / closed_form_m - 1.0));
    EXPECT_NEAR(m.unc_spread_m(t), closed_form_m, 0.02 * closed_form_m) << "target " << t;
    // A model fitted without directions answers both alike: the spread stays.
    EXPECT_GT(m.cor_spread_m(t), 0.8 * closed_form_m) << "target " << t;
  }
  std::printf(
      "spread between directions: unc max %.4f mean %.4f mm, cor max %.4f mean %.4f mm; "
      "closed form matched within %.2f %%\n",
      1e3 * m.unc_max_spread_m, 1e3 * m.unc_mean_spread_m, 1e3 * m.cor_max_spread_m,
      1e3 * m.cor_mean_spread_m, 100.0 * worst_relative);
}

}  // namespace multidirectional_test
}  // namespace vrreg
