// SPDX-License-Identifier: Apache-2.0
#pragma once
// The paper's experiments end to end on the simulated test beds (`vrreg reproduce`): for one seed,
// simulate UR5 datasets A1, A2, B and the KUKA grid and process them as sections 4.3 and 4.4 do,
// giving Table 1, Figures 4 and 7-11, Table 2 and Figures 5, 6, 12-15; for several seeds, the same
// in parallel (TBB), results in seed order whatever the thread count.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "vrreg/experiments/beyond_paper.hpp"
#include "vrreg/experiments/distance_sweep.hpp"
#include "vrreg/experiments/table1.hpp"
#include "vrreg/experiments/table2.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::experiments {

/// What to reproduce.
struct ReproductionOptions {
  std::uint64_t seed = 1;  ///< draws both robots and all noise; also Strategy 3's corner choice
  bool ur5 = true;         ///< Table 1 (A1, A2) and dataset B (Figures 7-11)
  bool lwr4 = true;        ///< Table 2 (KUKA)
  std::optional<simulation::TestbedErrorModel> ur5_errors{};   ///< empty: the test bed's defaults
  std::optional<simulation::TestbedErrorModel> lwr4_errors{};  ///< empty: the test bed's defaults
  double l_histogram_bin_m = 0.02e-3;                          ///< L histograms (Fig. 4-6) [m]
  double delta_tre_bin_m = 0.01e-3;  ///< Delta TRE histogram (Fig. 11) [m]
  bool beyond = false;  ///< also the field models beside RRBC (beyond_paper.hpp; slower)
  /// Throws InputError when neither test bed is on or a bin is not > 0.
  void validate() const;
};

/// Everything one seed produced.
struct Reproduction {
  std::uint64_t seed = 0;
  std::optional<Table1Entry> a1{};    ///< Table 1, octuplet 50 mm (d = 43.3 mm)
  std::optional<Table1Entry> a2{};    ///< Table 1, octuplet 25 mm (d = 21.7 mm); Fig. 4
  std::optional<DistanceSweep> b{};   ///< Figures 7-11
  std::optional<Table2> table2{};     ///< Table 2, Figures 5, 6, 12-15
  std::vector<BeyondTable> beyond{};  ///< ReproductionOptions::beyond: beyond the paper; else empty
};

/// Progress steps run_reproduction reports for `options` (one per dataset).
int reproduction_steps(const ReproductionOptions& options);

/// Simulates and processes one seed. `on_step` (may be empty) is called after each dataset. The
/// KUKA sigma_noise uses A1's sigma_opt of the same seed and the 0.05 mm repeatability (section
/// 5.2); without the UR5, the tracker's nominal noise.
Reproduction run_reproduction(const ReproductionOptions& options,
                              const std::function<void()>& on_step = {});

/// run_reproduction for each of `seeds` (options.seed ignored), seeds in parallel; results in the
/// order of `seeds`. `on_step` may be called from several threads at once.
std::vector<Reproduction> run_reproductions(const std::vector<std::uint64_t>& seeds,
                                            const ReproductionOptions& options,
                                            const std::function<void()>& on_step = {});

}  // namespace vrreg::experiments
