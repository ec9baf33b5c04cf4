// SPDX-License-Identifier: Apache-2.0
#pragma once
// The adaptive-planning study (docs/adaptive.md): on a simulated test bed, the loop plan next ->
// measure -> register -> plan next until it stops, at the paper's part points (the UR5's
// 120 dataset-B targets, the LWR 4+'s 150 grid targets in one arm configuration), against
// Procedure 1's octuplet cubes at each of dataset B's cube edges and against the full grid
// registered with the loop's correction, counting fiducials, readings and robot time.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/correction/interpolation.hpp"

namespace vrreg::experiments {

/// What to run.
struct AdaptiveStudyOptions {
  std::vector<std::string> robots{"ur5", "lwr4"};  ///< test beds ("ur5", "lwr4")
  std::vector<std::uint64_t> seeds{3, 4, 5};
  double seconds_per_move = 2.5;     ///< robot time per location visited [s]
  double seconds_per_reading = 0.1;  ///< robot time per tracker reading [s]
  int batch_size = 16;               ///< locations per adaptive batch
  /// Most fiducials of the adaptive loop; 0: a quarter of Procedure 1's at d_min.
  int budget = 0;
  /// The loop's goal, predicted RMS_T at the parts [m]; empty: 1.1 x the RMS_T Procedure 1
  /// measured at the smallest cube edge (d_min) in the same cell, the done-when's bar.
  std::optional<double> goal_sd_m{};
  /// PlanNextOptions::min_relative_gain: stop when a batch is expected to lower the predicted
  /// RMS_T by less than this fraction. 0: only the goal and the budget stop the loop (the REML
  /// refit moves the prediction by more than 1 % between batches, see docs/adaptive.md).
  double min_relative_gain = 0.0;
  double candidate_spacing_m = 0.02;  ///< adaptive candidate lattice spacing [m]
  /// What the loop and the grid correct with (the robot given for the joint-space model): the
  /// loop's measured RMS_T, and its predicted sd, goal and stop (PlanNextOptions::correction_sd
  /// unless kriging). The joint-space model by default: the test beds' error is the joints'
  /// transmission error on scales of 10-50 mm, which kriging on fiducials tens of millimetres
  /// apart does not resolve (docs/adaptive.md).
  InterpolationMethod interpolation = InterpolationMethod::kJoint;
  /// Procedure 1's cube edges a [m] (octuplets, d = sqrt(3)/2 a); empty: dataset B's ten,
  /// 50 to 5 mm.
  std::vector<double> cube_edges_m{};
  bool grid = true;  ///< also the full grid (UR5: dataset A1's fiducials; LWR: its grid's)
  /// Register and evaluate after every batch (the curve of RMS_T against fiducials); off: at
  /// STOP only (the other batches' measured_rms_t_m NaN).
  bool measure_every_batch = true;
  /// Throws InputError on an unknown robot, no seeds, or a value that is not finite and positive.
  void validate() const;
};

/// The state after one adaptive batch was measured (and before it, the space-filling start).
struct AdaptiveBatch {
  int batch = 0;           ///< 1-based
  int n_fiducials = 0;     ///< measured so far
  long long n_readings = 0;  ///< tracker readings so far (fiducials x repeats)
  double robot_time_s = 0.0;  ///< n_fiducials moves and n_readings readings at the options' rates
  double predicted_rms_t_m = 0.0;  ///< plan_next's predicted RMS_T now [m]; NaN without a model
  std::string predicted_by{};  ///< the method that predicted it (PlanNextResult::sd_method)
  std::string prediction_note{};  ///< why the study's method did not (PlanNextResult::sd_note)
  double measured_rms_t_m = 0.0;   ///< the options' correction of the fiducials so far, at all
                                   ///< targets (any outside its support uncorrected) [m]; NaN
                                   ///< when not measured (measure_every_batch off)
};

/// One adaptive loop on one test bed and seed.
struct AdaptiveRun {
  std::string robot{};
  std::uint64_t seed = 0;
  std::string interpolation{};  ///< the correction measured and predicted (auto: as chosen)
  std::vector<AdaptiveBatch> batches{};  ///< in order; the last is the state at STOP
  std::string stop_reason{};
  /// Measured / predicted RMS_T at STOP (the stopping prediction's honesty).
  [[nodiscard]] double measured_over_predicted() const;
};

/// A fixed plan measured at once: Procedure 1 at one cube edge, or the full grid.
struct FixedPlanRun {
  std::string robot{};
  std::uint64_t seed = 0;
  std::string plan{};         ///< "procedure1" or "grid"
  double cube_edge_m = 0.0;   ///< Procedure 1: a [m]; grid: its spacing [m]
  double d_m = 0.0;           ///< Procedure 1: sqrt(3)/2 a [m]; grid: 0
  std::string interpolation{};  ///< "octuplet" (the paper's Eq. 7), or the study's for the grid
  int n_fiducials = 0;
  long long n_readings = 0;
  double robot_time_s = 0.0;
  double rms_t_m = 0.0;  ///< corrected RMS_T at the targets [m] (any not corrected: uncorrected)
};

/// The done-when criteria for one test bed and seed.
struct AdaptiveVerdict {
  std::string robot{};
  std::uint64_t seed = 0;
  double procedure1_dmin_rms_t_m = 0.0;  ///< Procedure 1 at the smallest cube edge [m]
  double goal_sd_m = 0.0;                ///< the loop's goal [m]
  int procedure1_dmin_fiducials = 0;
  double adaptive_rms_t_m = 0.0;  ///< the loop's measured RMS_T at STOP [m]
  int adaptive_fiducials = 0;
  double measured_over_predicted = 0.0;
  bool reaches = false;  ///< adaptive RMS_T <= 1.1 x Procedure 1's at d_min
  bool quarter = false;  ///< 4 x adaptive fiducials <= Procedure 1's at d_min
  bool honest = false;   ///< measured / predicted within 0.8 .. 1.2
};

/// Every run of the study, robot-major then seed.
struct AdaptiveStudyResult {
  AdaptiveStudyOptions options{};
  std::vector<AdaptiveRun> adaptive{};
  std::vector<FixedPlanRun> fixed{};  ///< per robot and seed: Procedure 1 by edge, then grid
  std::vector<AdaptiveVerdict> verdicts{};
  std::vector<int> n_targets{};  ///< per robot (options.robots order)
};

/// `options` cut down for a quick run (`--quick`, tests): Procedure 1 at a = 50 and 5 mm only
/// (d_max and d_min), no grid, adaptive batches of 60, RMS_T measured at STOP only.
AdaptiveStudyOptions quick_study_options(AdaptiveStudyOptions options);

/// Runs the study: per robot and seed (seeds in parallel) the adaptive loop (planning::plan_next
/// with the goal, batch, budget and gain rule of the options; each batch simulated with simulation::simulate_plan
/// at a time of its own, so its noise is drawn afresh; registration with options.interpolation after each batch),
/// Procedure 1 (planning::make_plan, half-width a/2 and spacing a: the octuplet of section 6's
/// cube at d = sqrt(3)/2 a, registered with the paper's octuplet correction, Eq. 7) and the grid
/// (options.interpolation), each evaluated at the same measured targets (Eq. 4).
AdaptiveStudyResult run_adaptive_study(const AdaptiveStudyOptions& options);

}  // namespace vrreg::experiments
