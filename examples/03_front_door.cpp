// SPDX-License-Identifier: Apache-2.0
// Example 3: the library's front door on your own arrays — no files, no internal types.
//
//   build/release/examples/example_03_front_door
//
// A cell engineer has, from their own robot and tracker code, the commanded robot positions and
// the measured sensor positions of a 4 x 4 x 4 grid of fiducials (here simulated: a tracker 2 m
// away, a robot whose error changes smoothly over the volume). Three calls:
//   1. vrreg::register_fiducials: {R, tau} (Eq. 2), sigma_L (Eq. 1), sigma_noise and rho (Eq. 9),
//      the RRBC corrections (Eq. 6), all in a model;
//   2. vrreg::evaluate: TRE and RMS_T uncorrected and RRBC-corrected on independent targets
//      (Eq. 3, 4, 7, 8), gamma and N_bad;
//   3. vrreg::correct: the robot-frame position to command for points the sensor sees.
// docs/library.md walks through it.
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <exception>

#include "vrreg/vrreg.hpp"

namespace {

// What the tracker reports for the robot's commanded positions [m]: the arm lands off by a
// smooth error of up to ~0.4 mm, seen from a frame 2 m away and turned 0.5 rad about z.
vrreg::Points3 sense(const vrreg::Points3& commanded_robot_m) {
  const Eigen::Isometry3d T_sensor_robot =
      Eigen::Translation3d(0.1, -0.2, 2.0) * Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ());
  vrreg::Points3 out(3, commanded_robot_m.cols());
  for (Eigen::Index j = 0; j < out.cols(); ++j) {
    const Eigen::Vector3d p = commanded_robot_m.col(j);
    const Eigen::Vector3d error_m(2e-4 * std::sin(20 * p.y()), 3e-4 * p.x() * p.z() / 0.1,
                                  2e-4 * std::cos(15 * p.x()));
    out.col(j) = T_sensor_robot * (p + error_m);
  }
  return out;
}

// An n x n x n grid with `spacing_m`, its first node at `first_m`.
vrreg::Points3 grid(int n, double spacing_m, const Eigen::Vector3d& first_m) {
  vrreg::Points3 out(3, n * n * n);
  for (int i = 0; i < n * n * n; ++i) {
    out.col(i) = first_m + spacing_m * Eigen::Vector3d(i % n, i / n % n, i / (n * n));
  }
  return out;
}

}  // namespace

int main() {
  try {
    // Fiducials every 50 mm; targets at the centres of their cubes (independent of the fit).
    vrreg::MeasuredPoints fiducials;
    fiducials.robot_m = grid(4, 0.05, Eigen::Vector3d(0.35, -0.1, 0.15));
    fiducials.sensor_m = sense(fiducials.robot_m);
    vrreg::MeasuredPoints targets;
    targets.robot_m = grid(3, 0.05, Eigen::Vector3d(0.375, -0.075, 0.175));
    targets.sensor_m = sense(targets.robot_m);

    // 1. Register. The robot's repeatability (0.05 mm) makes sigma_noise and rho meaningful.
    vrreg::RegisterOptions options;
    options.sigma_rep_m = 0.05e-3;
    const vrreg::RegisterResult r = vrreg::register_fiducials(fiducials, options);
    std::printf(
        "registered %zu fiducials: FRE %.3f mm, sigma_L %.3f mm, rho %.1f (%s)\n", r.n_registered,
        1e3 * r.registration.fre_m, 1e3 * r.rigid_body.sigma_l_m, r.noise.rho.value_or(0.0),
        r.noise.rho.value_or(0.0) > vrreg::kRhoThreshold ? "RRBC should help" : "noise dominates");

    // 2. Evaluate on the targets: what a peg would really miss by.
    const vrreg::EvaluateResult e = vrreg::evaluate(r.model, targets);
    std::printf(
        "%d targets (%s): RMS_T %.3f mm uncorrected, %.3f mm with RRBC, gamma %.0f %%, "
        "N_bad %d\n",
        e.summary.n_targets, e.correction.layout.c_str(), 1e3 * e.summary.unc_rms_t_m,
        1e3 * e.summary.cor_rms_t_m, 100 * e.summary.gamma, e.summary.n_bad);

    // 3. Correct: a hole the sensor sees; command the robot to the corrected position.
    vrreg::MeasuredPoints hole;
    hole.sensor_m = sense(Eigen::Vector3d(0.42, -0.03, 0.21));
    const vrreg::CorrectResult c = vrreg::correct(r.model, hole);
    const Eigen::Vector3d command_mm = 1e3 * c.correction.corrected_robot_m.col(0);
    std::printf("hole: command the robot to (%.3f, %.3f, %.3f) mm (it is at 420, -30, 210 mm)\n",
                command_mm.x(), command_mm.y(), command_mm.z());
    return 0;
  } catch (const vrreg::InputError& e) {  // bad input: one line that says what is wrong
    std::fprintf(stderr, "example_03: %s\n", e.what());
    return 1;
  }
}
