// SPDX-License-Identifier: Apache-2.0
#pragma once
// Table 2 (paper sections 4.4, 5.2; Figures 5, 6, 12-15): the KUKA grid, each location measured in
// every arm configuration, processed per configuration m by Strategy 1 (labels as the IK listed
// them), Strategy 2 (labels along the visiting path) and Strategy 3 (one registration from the
// volume corners, each target corrected from the corner fiducials nearest its configuration).
#include <cstdint>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/experiments/rrbc_run.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/planning/strategy2_labels.hpp"

namespace vrreg::experiments {

/// How to process the KUKA data.
struct Table2Options {
  double cube_edge_m = 0.040;        ///< octuplet edge [m] (targets at the centres of 40 mm cubes)
  double sigma_opt_m = 0.058e-3;     ///< sigma_opt for sigma_noise (the paper: A1's) [m]
  double sigma_rep_m = 0.05e-3;      ///< specified repeatability for sigma_noise (Eq. 9) [m]
  std::uint64_t strategy3_seed = 1;  ///< Strategy 3: seed of the corners' random configurations
  kinematics::JointNorm norm = kinematics::JointNorm::kL2;  ///< Strategies 2, 3 (the paper: L2)
  double l_histogram_bin_m = 0.0;   ///< > 0: L histograms (Fig. 5, 6) in these bins [m]
  double match_tolerance_m = 1e-6;  ///< how far a fiducial may be from a cube corner [m]
  /// Throws InputError on a non-positive edge or tolerance or negative noise levels or bin.
  void validate() const;
};

/// Configuration m processed by Strategy s: one group of Table 2 cells.
struct Table2Entry {
  int config = 0;    ///< label m (Strategy 2: the relabelled m; Strategy 3: the IK's m)
  int strategy = 0;  ///< 1, 2 or 3
  /// Strategy 3: n_fiducials = 8 (registered), sigma_l_m = rho = 0 (not defined, as in the paper).
  RrbcRunFigures figures{};
  std::vector<std::string> target_points{};  ///< the targets' labels, in set order (Fig. 12-13)
  Points3 target_robot_m{};                  ///< their nominal robot positions [m]
};

/// Table 2 and what Procedure 2 did.
struct Table2 {
  std::vector<int> configs{};                  ///< configuration labels, ascending
  planning::Strategy2Summary strategy2{};      ///< switched points / locations (paper: 14 %)
  double sigma_noise_m = 0.0;                  ///< Eq. 9 from the options (paper: 0.077 mm)
  std::vector<std::size_t> strategy3_corners{};  ///< Strategy 3's registered fiducials (set index)
  std::vector<Table2Entry> entries{};            ///< per configuration, Strategies 1, 2, 3
  /// The entry of configuration `config` and strategy `strategy`; throws InputError if absent.
  [[nodiscard]] const Table2Entry& at(int config, int strategy) const;
  /// True when Strategy 2 relabelled some location the IK had listed as `config`.
  [[nodiscard]] bool switched(int config) const;
};

/// Table 2 (section 4.4) on `set` (config column and joints required; points visited in set
/// order). Throws InputError on bad options or a set Strategy 2 or 3 cannot use.
Table2 run_table2(const MeasurementSet& set, const Table2Options& options);

}  // namespace vrreg::experiments
