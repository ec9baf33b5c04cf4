// SPDX-License-Identifier: Apache-2.0
// Orientation correction across the test beds' scenarios, not at the default cell only: tool
// tilt (0, 10, 30 deg from straight down), one fixed orientation or a tool turned 0-25 deg at
// every location, a rigid body mounted 0.5 deg off, the UR5 and the KUKA LWR 4+, a lattice and
// a scattered layout. For every method that corrects orientations and for auto, on held-out
// targets: never worse than uncorrected, the predicted sd calibrated (RMS angle / sd 0.7-1.4),
// and auto near the noise floor (a noise-free re-simulation of the same seed): the test beds'
// physics is joint-based (DH errors, transmission errors, gravity compliance) and, in the
// lost-motion scenarios, per-joint lost motion along a serpentine raster. Each scenario's
// figures are printed as `sweep | ...` lines: the table in docs/orientation.md. The same fits
// check the positions: never worse than none at the targets (the guard), and auto's choice
// against the best candidate there (`choice | ...` lines), and the lost-motion term: applied
// exactly where the arm has lost motion, and then better than auto without it (`lost motion |`).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "vrreg/core/random.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/experiments/beyond_paper.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"
#include "vrreg_test.hpp"

namespace vrreg::experiments {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct Scenario {
  std::string name;
  bool kuka = false;
  double tilt_deg = 0.0;     ///< the tool tilted from straight down about the base's y axis
  bool varied = false;       ///< each location turned 0-25 deg about a random axis besides
  bool mounted_off = true;   ///< the rigid body mounted 0.5 deg off the tool frame
  bool scattered = false;    ///< random locations instead of a lattice
  bool lost_motion = false;  ///< per-joint lost motion (experiments::lost_motion_errors' plays)
};

// The locations: a 6 x 6 x 5 lattice at 40 mm (or 180 random points in its box) as fiducials
// and 60 random points inside as targets, each with its commanded orientation, sent through the
// test bed's IK from its home posture.
std::vector<simulation::CommandedLocation> plan_of(const simulation::Testbed& tb,
                                                   const Scenario& s) {
  Random rng(s.kuka ? 41 : 43);
  const Eigen::Vector3d lo = tb.volume_centre_m - Eigen::Vector3d(0.1, 0.1, 0.08);
  std::vector<std::pair<Eigen::Vector3d, Role>> points;
  for (int i = 0; i < 180; ++i) {
    // With lost motion, a serpentine raster (x reversed on every other row): each joint is
    // approached from both sides, so the plays can be told from a constant offset.
    const int x = s.lost_motion && (i / 6) % 2 == 1 ? 5 - i % 6 : i % 6;
    const Eigen::Vector3d lattice(0.04 * x, 0.04 * ((i / 6) % 6), 0.04 * (i / 36));
    const Eigen::Vector3d random(rng.uniform(0.0, 0.2), rng.uniform(0.0, 0.2),
                                 rng.uniform(0.0, 0.16));
    points.emplace_back(lo + (s.scattered ? random : lattice), Role::kFiducial);
  }
  for (int i = 0; i < 60; ++i) {
    points.emplace_back(lo + Eigen::Vector3d(rng.uniform(0.01, 0.19), rng.uniform(0.01, 0.19),
                                             rng.uniform(0.01, 0.15)),
                        Role::kTarget);
  }
  const Eigen::Matrix3d tilted =
      tb.tcp_rotation * rotation_exp(Eigen::Vector3d(0.0, s.tilt_deg * kDeg, 0.0));
  std::vector<simulation::CommandedLocation> plan;
  kinematics::JointVector q_from = tb.home_q_rad;
  for (std::size_t k = 0; k < points.size(); ++k) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = points[k].first;
    T.linear() = tilted;
    if (s.varied) {
      const Eigen::Vector3d axis = rng.normal3(1.0).normalized();
      T.linear() = tilted * rotation_exp(axis * rng.uniform(0.0, 25.0 * kDeg));
    }
    const kinematics::IkResult ik = kinematics::inverse_kinematics_nearest(
        tb.nominal, T, q_from,
        s.kuka ? std::optional<double>(tb.arm_angle_rad) : std::optional<double>());
    if (!ik.ok()) continue;  // out of reach with this orientation: not planned
    simulation::CommandedLocation l;
    l.point = (points[k].second == Role::kTarget ? "T" : "F") + std::to_string(k);
    l.role = points[k].second;
    l.q_rad = ik.solutions.front().q_rad;
    l.robot_m = kinematics::forward_kinematics(tb.nominal, l.q_rad).translation();
    if (!s.kuka) q_from = l.q_rad;  // the UR controller: nearest the previous location's
    plan.push_back(l);
  }
  return plan;
}

MeasurementSet measured(const simulation::Testbed& tb, const Scenario& s, bool noise) {
  simulation::SimulationOptions o;
  o.seed = 7;
  simulation::TestbedErrorModel e = tb.default_errors;
  e.tracker.rigid_body_radius_m = 0.05;
  if (s.lost_motion) {
    e = lost_motion_errors(e, false);
    if (s.kuka) e.robot.lost_motion_rad.push_back(e.robot.lost_motion_rad.back());
  }
  o.errors = noise ? e : without_noise(e);
  if (s.mounted_off) o.body_mount_rotation_rad = Eigen::Vector3d(0.3, -0.35, 0.2) * kDeg;
  return to_measurement_set(simulation::simulate_plan(tb, plan_of(tb, s), o));
}

void check_scenario(const Scenario& s) {
  const simulation::Testbed tb = s.kuka ? simulation::lwr4_testbed() : simulation::ur5_testbed();
  const MeasurementSet set = measured(tb, s, true);
  const std::vector<std::size_t> targets = set.select(Role::kTarget);
  ASSERT_GE(targets.size(), 50u) << s.name;
  const MeasurementSet noise_free = measured(tb, s, false);
  const double floor_rad = angle_noise_floor_rad(set, noise_free, targets);
  const double floor_m = noise_floor_m(set, noise_free, targets);
  RegisterOptions reg;
  reg.rigid_body_statistics = false;
  reg.robot = tb.nominal;
  // Positions: RMS_T over every target as the robot gets it (a flagged target uncorrected).
  double auto_rms_t_m = 0.0;
  double auto_tre_over_sd = 0.0;  // RMS of TRE / predicted sd at the targets
  InterpolationMethod auto_chose = InterpolationMethod::kAuto;
  double best_rms_t_m = std::numeric_limits<double>::infinity();
  InterpolationMethod best = InterpolationMethod::kAuto;
  for (const InterpolationMethod m :
       {InterpolationMethod::kAuto, InterpolationMethod::kJoint, InterpolationMethod::kKriging,
        InterpolationMethod::kRbf, InterpolationMethod::kScattered,
        InterpolationMethod::kTrilinear}) {
    if (m == InterpolationMethod::kTrilinear && s.scattered) continue;  // needs a lattice
    reg.interpolation.method = m;
    const RegistrationModel model = register_fiducials(set, reg).model;
    ASSERT_TRUE(model.orientation_corrector) << s.name;
    const EvaluateResult r = evaluate(model, set);
    ASSERT_TRUE(r.orientation) << s.name;
    const double rms_t_m = root_mean_square(r.cor_tre_m);
    const double unc_rms_t_m = root_mean_square(r.unc_tre_m);
    // The positions' guard: never worse than none at the targets (a 2 % allowance for the
    // targets' own sampling: cross-validation judged on the fiducials).
    EXPECT_LE(rms_t_m, 1.02 * unc_rms_t_m) << s.name << ", " << to_string(m);
    // The lost-motion term enters where the arm has lost motion (auto and joint judge it by the
    // joint model, beside which the plays are fitted) and nowhere else.
    ASSERT_TRUE(model.corrector->lost_motion()) << s.name << ", " << to_string(m);
    const LostMotionTerm& term = *model.corrector->lost_motion();
    if (!s.lost_motion) {
      EXPECT_FALSE(term.applied) << s.name << ", " << to_string(m) << ": " << term.reason;
    } else if (m == InterpolationMethod::kAuto || m == InterpolationMethod::kJoint) {
      EXPECT_TRUE(term.applied) << s.name << ", " << to_string(m) << ": " << term.reason;
    }
    if (m == InterpolationMethod::kAuto) {
      auto_rms_t_m = rms_t_m;
      auto_tre_over_sd = r.calibration.rms_ratio;
      auto_chose = model.corrector->method();
    } else if (rms_t_m < best_rms_t_m) {
      best_rms_t_m = rms_t_m;
      best = m;
    }
    const OrientationEvaluation& o = *r.orientation;
    const std::string what = s.name + ", " + to_string(m) +
                             " (orientation: " + to_string(model.orientation_corrector->method()) +
                             ")";
    SCOPED_TRACE(what + ": uncorrected " + std::to_string(1e3 * o.unc_rms_rad) +
                 " mrad, corrected " + std::to_string(1e3 * o.cor_rms_rad) + " mrad, floor " +
                 std::to_string(1e3 * floor_rad) + " mrad, angle/sd " +
                 std::to_string(o.calibration.rms_ratio));
    // The table in docs/orientation.md comes from these lines.
    std::printf("sweep | %s | %s | %s | %.3f | %.3f | %.2f | %.2f | %s\n", s.name.c_str(),
                to_string(m), to_string(model.orientation_corrector->method()), 1e3 * o.unc_rms_rad,
                1e3 * o.cor_rms_rad, o.cor_rms_rad / floor_rad, o.calibration.rms_ratio,
                model.orientation_corrector->applied() ? "applied" : "not applied");
    // Never worse than no correction: applied only where cross-validation says it helps.
    EXPECT_LE(o.cor_rms_rad, o.unc_rms_rad);
    if (model.orientation_corrector->applied() && o.calibration.n > 0) {
      EXPECT_GT(o.calibration.rms_ratio, 0.7);
      EXPECT_LT(o.calibration.rms_ratio, 1.4);
    }
    // Auto within 1.3x the floor in every scenario; on the UR5 with the tool turned at every
    // location, by the wrist joints' cyclic (transmission) errors, which only orientations show.
    if (m == InterpolationMethod::kAuto) {
      EXPECT_LT(o.cor_rms_rad, 1.3 * floor_rad);
      if (s.varied && !s.kuka && !s.lost_motion) {  // cyclic: the transmission error
        EXPECT_NE(model.orientation_corrector->describe().find("cyclic joint-angle error"),
                  std::string::npos)
            << model.orientation_corrector->describe();
      }
    }
  }
  // With lost motion, auto with the term against auto without it, near the floor, and its sd
  // honest (RMS of TRE/sd; 0.7: the KUKA's joint model is conservative on a lattice under its
  // transmission ripple, with lost motion or without, docs/uncertainty.md).
  if (s.lost_motion) {
    reg.interpolation.method = InterpolationMethod::kAuto;
    reg.lost_motion = LostMotionMode::kOff;
    const double off_rms_t_m =
        root_mean_square(evaluate(register_fiducials(set, reg).model, set).cor_tre_m);
    std::printf("lost motion | %s | %.4f | %.4f | %.4f | %.2f\n", s.name.c_str(), 1e3 * floor_m,
                1e3 * auto_rms_t_m, 1e3 * off_rms_t_m, auto_tre_over_sd);
    EXPECT_LT(auto_rms_t_m, 0.98 * off_rms_t_m) << s.name;
    EXPECT_LT(auto_rms_t_m, 1.2 * floor_m) << s.name;
    EXPECT_GT(auto_tre_over_sd, 0.7) << s.name;
    EXPECT_LT(auto_tre_over_sd, 1.25) << s.name;
  }
  // Auto's choice for the positions against the best candidate at the held-out targets: the
  // `choice` lines are the table in docs/field-models.md.
  std::printf("choice | %s | %s | %.4f | %s | %.4f | %.3f | %.2f\n", s.name.c_str(),
              to_string(auto_chose), 1e3 * auto_rms_t_m, to_string(best), 1e3 * best_rms_t_m,
              auto_rms_t_m / best_rms_t_m, auto_tre_over_sd);
  EXPECT_LT(auto_rms_t_m, 1.25 * best_rms_t_m)
      << s.name << ": auto chose " << to_string(auto_chose);
}

class OrientationSweep : public ::testing::TestWithParam<Scenario> {};

TEST_P(OrientationSweep, NeverWorseCalibratedAndAutoAtTheFloor) {
  if (testing::sanitized()) GTEST_SKIP() << "four fits per scenario: release build only";
  check_scenario(GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, OrientationSweep,
    ::testing::Values(
        Scenario{"ur5_down_fixed", false, 0.0, false},
        Scenario{"ur5_tilt10_fixed", false, 10.0, false},
        Scenario{"ur5_tilt30_fixed", false, 30.0, false},
        Scenario{"ur5_tilt10_fixed_mounted_exactly", false, 10.0, false, false},
        Scenario{"ur5_down_varied", false, 0.0, true},
        Scenario{"ur5_tilt30_varied_scattered", false, 30.0, true, true, true},
        Scenario{"ur5_tilt10_fixed_scattered", false, 10.0, false, true, true},
        Scenario{"kuka_tilt10_fixed", true, 10.0, false},
        Scenario{"kuka_down_varied", true, 0.0, true},
        Scenario{"ur5_tilt10_fixed_lost_motion", false, 10.0, false, true, false, true},
        Scenario{"ur5_tilt30_varied_lost_motion", false, 30.0, true, true, false, true},
        Scenario{"kuka_tilt10_fixed_lost_motion", true, 10.0, false, true, false, true}),
    [](const ::testing::TestParamInfo<Scenario>& scenario) { return scenario.param.name; });

}  // namespace
}  // namespace vrreg::experiments
