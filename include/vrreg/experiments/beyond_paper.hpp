// SPDX-License-Identifier: Apache-2.0
#pragma once
// Beyond the paper (`vrreg reproduce --beyond`, docs/reproduction.md): on the simulated datasets,
// the paper's RRBC row beside the field models (linear, trilinear, rbf, kriging, joint, auto),
// each with its corrected RMS_T, that RMS_T over the noise floor (what a perfect correction of
// the systematic error would leave) and how honest its predicted sd per target is.
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/interpolation.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::experiments {

/// One way of correcting the targets of a dataset, on one seed.
struct BeyondRow {
  std::string method{};  ///< "octuplet", "strategy 2", "strategy 3" or a field model's name
  bool ok = false;     ///< false: not applicable or not built yet; `note` says why (shown "-")
  std::string note{};
  double cor_rms_t_m = std::numeric_limits<double>::quiet_NaN();  ///< Eq. 4 after correction
  /// RMS of TRE / sigma_pred over the targets with a predicted sd (NaN: none predicted).
  double calibration_rms_ratio = std::numeric_limits<double>::quiet_NaN();
  double within_2sigma = std::numeric_limits<double>::quiet_NaN();  ///< fraction TRE <= 2 sigma
  int n_flagged = 0;   ///< targets the method could not correct (they keep their uncorrected TRE)
  std::string chosen{};  ///< auto: the method cross-validation chose
  /// Orientations (rigid-body marker): the corrected RMS angle error [rad] and RMS of angle
  /// error / sigma_pred; NaN without orientations or a prediction.
  double cor_rms_angle_rad = std::numeric_limits<double>::quiet_NaN();
  double angle_calibration_rms_ratio = std::numeric_limits<double>::quiet_NaN();
};

/// One dataset (or one KUKA configuration) of the beyond table, on one seed.
struct BeyondTable {
  std::string key{};      ///< JSON pointer segment: A1, A2, B, A1_thinned, A1_cube27, kuka_1 ...
  std::string dataset{};  ///< what it is, for the printed table
  int n_fiducials = 0;  ///< fiducials of the field models' registration
  int n_targets = 0;
  double unc_rms_t_m = 0.0;    ///< uncorrected RMS_T with the field models' registration
  double noise_floor_m = 0.0;  ///< noise_floor_m of the targets
  /// Orientations (rigid-body marker): uncorrected RMS angle error and its noise floor [rad];
  /// NaN when the dataset has no orientations.
  double unc_rms_angle_rad = std::numeric_limits<double>::quiet_NaN();
  double angle_noise_floor_rad = std::numeric_limits<double>::quiet_NaN();
  std::vector<BeyondRow> rows{};
};

/// What to run: the same test beds, seed and error models as the reproduction.
struct BeyondOptions {
  std::uint64_t seed = 1;
  bool ur5 = true;   ///< A1, A2, B, A1 thinned, A1 cube of 27
  bool lwr4 = true;  ///< the KUKA grid, per configuration
  std::optional<simulation::TestbedErrorModel> ur5_errors{};
  std::optional<simulation::TestbedErrorModel> lwr4_errors{};
  /// The field methods to run; empty: all of beyond_field_methods() (tests pick cheap ones).
  std::vector<InterpolationMethod> methods{};
  /// A1 (with its thinned and cube27 subsets) and the KUKA, on the default error models, get a
  /// rigid body of 4 spheres on this radius, so that their tables have orientations too (0:
  /// spheres, positions only); given error models are kept as they are. A2 and B stay spheres:
  /// their orientation fields on 8 000-9 000 fiducials add a minute to the 8 of the run.
  double rigid_body_radius_m = 0.05;
  /// With ur5: A1_backlash and A1_mixed, half of A1 with lost motion (lost_motion_errors).
  bool lost_motion = true;
};

/// The UR5 lost-motion cells' robot errors (A1_backlash, A1_mixed): per-joint lost motion of
/// 0.8, 0.2, 0.15, 0.7, 0.6, 0.4 arc-min (the wrist and base joints' gears larger, the
/// gravity-preloaded shoulder and elbow smaller) on `base` without its transmission error
/// (backlash), or on `base` with gravity sag (the UR5's link masses on joints of 1e5 / 3e4
/// N m / rad, about 0.2 mm at the tool) and 3 K of aluminium's thermal growth (mixed).
simulation::TestbedErrorModel lost_motion_errors(simulation::TestbedErrorModel base, bool mixed);

/// The field methods of the table, in printed order.
const std::vector<InterpolationMethod>& beyond_field_methods();

/// Steps run_beyond_paper reports through `on_step` (one per simulated dataset).
int beyond_steps(const BeyondOptions& options);

/// All tables of one seed: A1, A1 thinned, A1 cube27, A2, B, then kuka_<m> per configuration.
std::vector<BeyondTable> run_beyond_paper(const BeyondOptions& options,
                                          const std::function<void()>& on_step = {});

/// `errors` with the tracker's reading noise and the robot's repeatability set to zero: the
/// simulation draws the same robot, so a re-simulation of the same seed is the noisy run's
/// systematic part alone (Random::normal(sigma) = sigma * normal(): the streams do not shift).
simulation::TestbedErrorModel without_noise(simulation::TestbedErrorModel errors);

/// The noise floor: RMS over `rows` of |measured - noise-free| sensor position [m]. Correcting
/// each target by its exact systematic error leaves R (measured - noise-free) in the robot frame
/// (rigid registration, so the norm is kept): its own averaged tracker noise and repeatability.
/// Throws InputError when the two sets do not hold the same locations.
double noise_floor_m(const MeasurementSet& measured, const MeasurementSet& noise_free,
                     const std::vector<std::size_t>& rows);

/// The orientation noise floor: RMS over `rows` of the angle between the measured and the
/// noise-free sensor orientation [rad] (what correcting each target's orientation by its exact
/// systematic error leaves). Throws InputError when the sets differ or a row has no orientation.
double angle_noise_floor_rad(const MeasurementSet& measured, const MeasurementSet& noise_free,
                             const std::vector<std::size_t>& rows);

/// Targets of a set, as positions in set.select(Role::kTarget), forming one table.
struct TargetGroup {
  std::string key{};
  std::string dataset{};
  std::vector<std::size_t> positions{};
};

/// Registers all fiducials of `measured` (robot stored for the joint model) and corrects all its
/// targets with every method of `methods` (empty: beyond_field_methods()); the paper's octuplet
/// first when `octuplet_edge_m` is given. One table per group; a method that throws is a row
/// with ok = false.
std::vector<BeyondTable> beyond_tables(const MeasurementSet& measured,
                                       const MeasurementSet& noise_free,
                                       const kinematics::SerialChain& robot, double sigma_rep_m,
                                       const std::vector<TargetGroup>& groups,
                                       std::optional<double> octuplet_edge_m,
                                       const std::vector<InterpolationMethod>& methods = {});

}  // namespace vrreg::experiments
