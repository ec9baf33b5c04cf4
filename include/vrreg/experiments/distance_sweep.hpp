// SPDX-License-Identifier: Apache-2.0
#pragma once
// Dataset B (paper sections 4.1, 4.3, 5.1; Figures 7-11): one registration from all fiducials,
// then every target corrected from the octuplet of each cube size in turn (weights 1/8), giving
// corrected RMS_T and N_bad against the target-fiducial distance d = sqrt(3)/2 a.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/metrics/rigid_body.hpp"

namespace vrreg::experiments {

/// The cube edges of dataset B: 50, 45, ..., 5 mm [m].
std::vector<double> dataset_b_cube_edges_m();

/// What to sweep.
struct DistanceSweepOptions {
  std::vector<double> cube_edges_m = dataset_b_cube_edges_m();  ///< largest first [m]
  double match_tolerance_m = 1e-6;   ///< how far a fiducial may be from a cube corner [m]
  double delta_tre_bin_m = 0.01e-3;  ///< bin of the Delta TRE histogram (Fig. 11) [m]
  /// Throws InputError on an empty or non-positive list of edges or a bad tolerance or bin.
  void validate() const;
};

/// One cube size (one point of Figures 7 and 8).
struct SweepStep {
  double cube_edge_m = 0.0;      ///< a [m]
  double d_m = 0.0;              ///< sqrt(3)/2 a [m]
  double cor_rms_t_m = 0.0;      ///< Fig. 7
  double gamma = 0.0;            ///< (unc - cor) / unc, a fraction
  int n_bad = 0;                 ///< Fig. 8: targets whose TRE got worse
  int n_flagged = 0;             ///< targets without a complete octuplet (left uncorrected)
  std::vector<int> bad_targets{};  ///< indices into DistanceSweep::target_points (Fig. 9, 10)
  Eigen::VectorXd cor_tre_m{};     ///< TRE(T^_X(n), d) per target
};

/// The sweep: uncorrected errors once, corrected errors per cube size.
struct DistanceSweep {
  int n_fiducials = 0;
  std::vector<std::string> target_points{};  ///< the targets' labels, in set order
  Points3 target_robot_m{};                  ///< their nominal robot positions [m] (Fig. 10)
  Eigen::VectorXd unc_tre_m{};               ///< TRE(T_X(n)) per target
  double unc_rms_t_m = 0.0;
  std::vector<SweepStep> steps{};  ///< in options.cube_edges_m order
  /// Fig. 11: TRE(T^_X) - TRE(T_X) where it improved (< 0), at the smallest cube [m].
  Eigen::VectorXd delta_tre_at_d_min_m{};
  Histogram delta_tre_histogram{};  ///< of delta_tre_at_d_min_m, bins options.delta_tre_bin_m
  /// The step with the largest / smallest d.
  [[nodiscard]] const SweepStep& at_d_max() const;
  [[nodiscard]] const SweepStep& at_d_min() const;
};

/// Runs dataset B's processing (section 4.3) on `set`: registration from all its fiducials (Eq. 2),
/// corrections epsilon_j (Eq. 6), then for each cube edge the octuplet around each target's
/// nominal position (Eq. 7, 8). A corner measured more than once (neighbouring targets' cubes)
/// takes the reading nearest the target's in Location::source_line order. Throws InputError on
/// bad options or a set without targets or with fewer than 3 fiducials.
DistanceSweep run_distance_sweep(const MeasurementSet& set, const DistanceSweepOptions& options);

}  // namespace vrreg::experiments
