// SPDX-License-Identifier: Apache-2.0
#pragma once
// How well the robust check (RegisterOptions::robust, correction/outliers.hpp) finds a bad
// fiducial on simulated UR5 A1 cells: per seed, the clean cell, one fiducial displaced
// by 1 mm and by 2 mm in a random direction, and two fiducials' sensor readings swapped; each
// registered with and without --robust and evaluated on the cell's targets (RRBC, Eq. 6-8).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/correction/outliers.hpp"

namespace vrreg::experiments {

/// Options of robust_study.
struct RobustStudyOptions {
  int seeds = 30;  ///< cells: seeds first_seed .. first_seed + seeds - 1
  std::uint64_t first_seed = 1;
  std::optional<double> sigma_rep_m{};  ///< as `register --sigma-rep-mm`; empty: not given
  OutlierOptions outliers{};
  /// Throws InputError on fewer than 1 seed.
  void validate() const;
};

/// What is done to a clean cell.
enum class RobustScenario { kClean, kDisplaced1mm, kDisplaced2mm, kSwapped };

/// One cell under one scenario.
struct RobustStudyCell {
  std::uint64_t seed = 0;
  RobustScenario scenario = RobustScenario::kClean;
  std::vector<std::string> planted{};  ///< the bad fiducials (empty when clean)
  bool found = false;                ///< every planted fiducial rejected (clean: true)
  int good_rejected = 0;             ///< rejected fiducials that were not planted
  double planted_sigmas = 0.0;       ///< smallest deviation of a planted one, in sigmas (if found)
  double sigma_m = 0.0;              ///< the scale the check used
  double sigma_noise_m = 0.0;        ///< sigma_noise (Eq. 9) of the cell; 0 when unknown
  double threshold_sigmas = 0.0;     ///< the bound
  int filled = 0;                    ///< rejected fiducials kept with their neighbours' correction
  int dropped = 0;                   ///< rejected fiducials dropped (too few neighbours)
  bool scale_is_noise = false;
  double plain_cor_rms_t_m = 0.0;   ///< corrected RMS_T registered without --robust
  double robust_cor_rms_t_m = 0.0;  ///< corrected RMS_T with --robust
};

/// All cells, scenario-major.
struct RobustStudy {
  RobustStudyOptions options{};
  std::vector<RobustStudyCell> cells{};
};

/// Runs the study (seeds in parallel; the same options give the same numbers).
RobustStudy robust_study(const RobustStudyOptions& options);

/// The rate table: per scenario, cells, found, cells without a good fiducial rejected, RMS_T with
/// and without --robust (mean, worst ratio), as printed by `vrreg robust-study`.
std::string robust_study_text(const RobustStudy& study);

const char* to_string(RobustScenario scenario);

}  // namespace vrreg::experiments
