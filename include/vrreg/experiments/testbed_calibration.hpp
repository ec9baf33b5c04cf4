// SPDX-License-Identifier: Apache-2.0
#pragma once
// Calibration of the simulated test beds against the paper (design.md 5): simulate the
// datasets for a list of seeds, run the paper's pipeline on each and compare the medians with
// the acceptance bands (UR5 Table 1 and section 5.1, KUKA Table 2 Strategy 1).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/experiments/rrbc_run.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::experiments {

/// What to run.
struct CalibrationOptions {
  std::vector<std::uint64_t> seeds = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  std::optional<simulation::TestbedErrorModel> ur5_errors{};   ///< empty: the test bed's defaults
  std::optional<simulation::TestbedErrorModel> lwr4_errors{};  ///< empty: the test bed's defaults
  bool ur5 = true;
  bool lwr4 = true;
};

/// UR5 figures of one seed: A1 and A2 with octuplets of 50 and 25 mm, B over its ten cubes.
struct Ur5SeedFigures {
  std::uint64_t seed = 0;
  RrbcRunFigures a1{};
  RrbcRunFigures a2{};
  double b_unc_rms_t_m = 0.0;
  std::vector<double> b_cube_edge_m{};  ///< 50 mm down to 5 mm
  std::vector<double> b_cor_rms_t_m{};  ///< per cube edge
  std::vector<int> b_n_bad{};           ///< per cube edge
  double seconds = 0.0;               ///< simulation + pipeline time
};

/// KUKA figures of one seed: per configuration label, Strategies 1 and 2 (octuplet 40 mm).
struct Lwr4SeedFigures {
  std::uint64_t seed = 0;
  double switched_points_fraction = 0.0;     ///< nominal points Strategy 2 reorders (paper: 0.14)
  double switched_locations_fraction = 0.0;  ///< (point, config) locations it relabels
  std::array<RrbcRunFigures, 4> strategy1{};
  std::array<RrbcRunFigures, 4> strategy2{};
  double seconds = 0.0;
};

/// Everything a calibration run produced.
struct CalibrationReport {
  std::vector<Ur5SeedFigures> ur5{};
  std::vector<Lwr4SeedFigures> lwr4{};
};

/// Simulates A1, A2 and B of the UR5 test bed for `seed` and runs the pipeline on them.
Ur5SeedFigures calibrate_ur5(const simulation::Testbed& testbed, std::uint64_t seed,
                             const std::optional<simulation::TestbedErrorModel>& errors);

/// Simulates the KUKA grid for `seed` and runs Strategies 1 and 2; `sigma_opt_m` (e.g. A1's of
/// the same seed) enters sigma_noise, as in the paper (K = 1 gives no estimate of its own).
Lwr4SeedFigures calibrate_lwr4(const simulation::Testbed& testbed, std::uint64_t seed,
                               const std::optional<simulation::TestbedErrorModel>& errors,
                               double sigma_opt_m);

/// Runs every seed of `options`.
CalibrationReport run_testbed_calibration(const CalibrationOptions& options);

/// The report as Markdown: per-seed tables, medians against the acceptance bands, verdicts.
std::string format_calibration_markdown(const CalibrationReport& report);

/// True when every acceptance band of the issue is met by `report`'s medians (and per seed where
/// the band is per seed).
bool calibration_passes(const CalibrationReport& report);

}  // namespace vrreg::experiments
