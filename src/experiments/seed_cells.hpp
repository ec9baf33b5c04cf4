// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to experiments: a study's cells, seeds first_seed .. first_seed + n - 1, each run
// under every scenario, seeds in parallel; the results scenario-major, the same for any thread
// count (each seed writes only its own slots).
#include <cstdint>
#include <span>
#include <vector>

#include "parallel_tasks.hpp"

namespace vrreg::experiments::detail {

/// `make(seed)` builds a seed's cell once; `run(cell, seed, scenario)` gives one result.
template <typename Result, typename Scenario, typename Make, typename Run>
std::vector<Result> seed_cells(std::uint64_t first_seed, std::size_t n_seeds,
                               std::span<const Scenario> scenarios, Make&& make, Run&& run) {
  std::vector<Result> out(n_seeds * scenarios.size());
  parallel_tasks(n_seeds, [&](std::size_t s) {
    const std::uint64_t seed = first_seed + s;
    const auto cell = make(seed);
    for (std::size_t k = 0; k < scenarios.size(); ++k) out[k * n_seeds + s] = run(cell, seed, scenarios[k]);
  });
  return out;
}

}  // namespace vrreg::experiments::detail
