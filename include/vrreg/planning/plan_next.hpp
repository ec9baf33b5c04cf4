// SPDX-License-Identifier: Apache-2.0
#pragma once
// Adaptive planning: where to measure the next fiducials so that the kriging correction's
// predicted error at the part points falls fastest, and when to stop (docs/adaptive.md).
// Kriging's posterior variance depends on where fiducials are, not on what they measure, so
// once the hyperparameters are fitted on the fiducials measured so far, a batch's effect on the
// predicted sd at the parts is known before it is measured. Without enough data for a fit, the
// batch is a space-filling (greedy maximin) design over the parts' volume.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/correction/kriging.hpp"
#include "vrreg/correction/kriging_design.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/planning/arm_configuration.hpp"
#include "vrreg/planning/plan.hpp"

namespace vrreg::planning {

/// Fiducials measured so far, one column per location (repeat readings averaged).
struct MeasuredFiducials {
  Points3 robot_m{};   ///< commanded TCP positions, robot base frame [m]
  Points3 sensor_m{};  ///< measured positions, sensor frame [m]
};

/// The fiducial rows of a measurement set (repeat readings averaged; each needs its robot
/// position) and the noise of one averaged reading, sigma_opt / sqrt(K) with K the median
/// readings per location (empty without repeats): the kriging nugget's floor and the noise
/// floor's sensor term. Throws InputError on a fiducial without a robot position.
struct FiducialsWithNoise {
  MeasuredFiducials fiducials{};
  std::optional<double> noise_sd_m{};
};
FiducialsWithNoise measured_fiducials(const MeasurementSet& set);

/// The predicted sd of the correction a loop will correct with, when that is not kriging (e.g.
/// the joint-space model), at the part points: what plan_next's goal and stop rule then judge.
struct CorrectionSd {
  /// Per part point (input order) [m]; empty when the correction cannot give one yet (`note`).
  std::optional<Eigen::VectorXd> sd_m{};
  std::string method{};  ///< the method that answered (auto: the one it chose)
  std::string note{};    ///< why sd_m is empty (too few fiducials, parts outside its support)
};
/// Called with the part points and their joints (reachable, plan_next's arm configuration).
using CorrectionSdAtParts = std::function<CorrectionSd(const std::vector<PartPlan>& parts)>;

/// What to plan next.
struct PlanNextOptions {
  /// Goal: the predicted RMS_T at the parts, sqrt(mean over parts of sd^2) [m] (> 0), unless
  /// goal_floor_multiple is set (then 0).
  double goal_sd_m = 0.0;
  /// Goal as a multiple (> 0) of the noise floor sqrt(3 (sigma_rep^2 + noise_sd^2)) (design.md),
  /// instead of goal_sd_m. The floor is unknown while noise_sd_m is (no repeat readings yet):
  /// then no batch stops on the goal.
  std::optional<double> goal_floor_multiple{};
  /// Robot repeatability sigma_rep [m] for the noise floor (0: not known, the floor counts the
  /// sensor only).
  double sigma_rep_m = 0.0;
  int batch_size = 8;  ///< locations per batch
  int budget = 64;     ///< most fiducials in all, measured and planned
  /// Candidate lattice spacing [m] over the parts' bounding box grown by margin_m.
  double candidate_spacing_m = 0.02;
  double margin_m = 0.02;
  /// Fewer measured fiducials than this: no model is fitted, the batch is space-filling (the
  /// kriging corrector needs 12).
  int min_fit_fiducials = 12;
  /// Stop when the batch is expected to lower the predicted sd at the parts by less than this
  /// fraction: the rest is the noise of the parts' own measurement (the nugget).
  double min_relative_gain = 0.01;
  /// Known sd of one fiducial correction (e.g. from repeats) [m]: a floor on the fitted nugget.
  std::optional<double> noise_sd_m{};
  /// Per-axis hyperparameters to use instead of a REML fit on the measured fiducials (e.g. from
  /// an earlier cell); their trend degree is the one the corrector would use.
  std::optional<std::array<KrigingHyperparameters, 3>> hyperparameters{};
  KrigingKernel kernel = KrigingKernel::matern52;  ///< with given hyperparameters
  /// The correction the measured fiducials will be corrected with, when it is not kriging
  /// (pipeline::correction_sd_at_parts): its predicted sd at the parts is the "now" that the
  /// goal is judged on; "after" is not predicted (NaN) and min_relative_gain does not apply
  /// (the goal and the budget stop the loop). The batch is still the one that lowers kriging's
  /// posterior variance most. Empty, or an answer without sd: kriging's own prediction.
  CorrectionSdAtParts correction_sd{};
  ArmConfigurationOptions arm{};   ///< tool orientation, norm, psi, home joints (as plan)
  std::string label_prefix = "n";  ///< location k (1-based, counting measured) is "<prefix>k"
  long long max_candidates = 50'000;
  /// Throws InputError on a bad field for `chain`.
  void validate(const kinematics::SerialChain& chain) const;
};

/// Stop measuring, or measure the planned batch.
enum class PlanNextDecision { kContinue, kStop };
/// Lower-case name ("continue", "stop").
const char* to_string(PlanNextDecision decision);

/// The next batch and the predictions behind it.
struct PlanNextResult {
  PlanStatus status = PlanStatus::kOk;  ///< kUnreachable: a part point has no joints
  std::string message{};                ///< why not ok
  PlanNextDecision decision = PlanNextDecision::kContinue;
  std::string reason{};           ///< e.g. "the goal is reached", "the budget is spent"
  bool space_filling = false;     ///< the batch is a space-filling design (no model fitted)
  std::vector<PartPlan> parts{};  ///< part points with their joints, input order
  std::vector<PlannedLocation> locations{};  ///< the batch, visiting order (empty on stop)
  /// Predicted sd of a corrected part point [m]: sqrt(sum over axes of the latent posterior
  /// variance times latent_sd_scale^2, plus the nugget variance), now and with the batch added
  /// (empty without a model); with correction_sd, that correction's now and NaN after.
  Eigen::VectorXd part_sd_now_m{};
  Eigen::VectorXd part_sd_after_m{};
  /// The goal used [m]: goal_sd_m, or the floor multiple times the noise floor; NaN when the
  /// floor is not known yet.
  double goal_sd_m = 0.0;
  /// sqrt(3 (sigma_rep^2 + noise_sd^2)) [m]; NaN without noise_sd_m.
  double noise_floor_m = 0.0;
  double rms_sd_now_m = 0.0;    ///< sqrt(mean part_sd_now_m^2) [m]; NaN without a model
  double rms_sd_after_m = 0.0;  ///< the same after the batch [m]; NaN without a model
  bool has_model = false;
  /// The method whose predicted sd part_sd_now_m is: "kriging", or the correction_sd's method.
  std::string sd_method = "kriging";
  std::string sd_note{};  ///< why correction_sd gave no sd, when it was asked and did not
  /// Per field component (when has_model): the kriging corrector's, on its inputs
  /// (KrigingCorrectorDesign); with given hyperparameters, Cartesian.
  std::array<KrigingDesignModel, 3> model{};
  std::array<double, 3> latent_sd_scale{1.0, 1.0, 1.0};
  Eigen::Index n_measured = 0;
  Eigen::Index n_candidates = 0;  ///< reachable lattice nodes in the parts' configurations
  double path_m = 0.0;            ///< travel through the batch in visiting order [m]
  [[nodiscard]] bool ok() const { return status == PlanStatus::kOk; }
};

/// Part points for a work volume instead of points: a lattice of spacing `spacing_m` [m] over the
/// box [min_m, max_m] (robot base frame), centred in it (on an axis of extent L, floor(L / spacing)
/// + 1 nodes, the same margin at both ends), named "v<k>" (k from 1, x fastest, then y, z).
/// Throws InputError on a non-finite corner, min above max on an axis, a spacing that is not
/// finite and positive, or more than max_points nodes.
std::vector<PartPoint> volume_part_points(const Eigen::Vector3d& min_m, const Eigen::Vector3d& max_m,
                                          double spacing_m, long long max_points = 10'000);

/// Plans the next batch of fiducial locations for `parts` (robot base frame) on `chain` (UR or
/// LWR 4+ structure) given the fiducials measured so far. Later batches pick greedily, each the
/// reachable candidate that most reduces the summed predicted variance at the parts given all
/// fiducials measured or picked (the rank-one kriging update); every location is reached in its
/// nearest part point's configuration; the batch is ordered by plan_cube_tour. Throws
/// InputError on bad options, parts or measurements.
PlanNextResult plan_next(const kinematics::SerialChain& chain, const std::vector<PartPoint>& parts,
                         const MeasuredFiducials& measured, const PlanNextOptions& options);

}  // namespace vrreg::planning
