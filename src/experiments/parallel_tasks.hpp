// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to experiments: independent tasks (a study's seeds, cells) in parallel, each run to the
// end even when another throws. An exception escaping a TBB task cancels its task group, and the
// cancellation reaches the parallel loops nested inside the other tasks (a corrector's folds, a
// kriging fit's starts), which then return with part of their work silently not done: the other
// seeds went on with half-filled results and crashed (seen: a segfault in a cross-validation
// fold while another seed's registration threw). Here no exception leaves a task; after every
// task has finished, the one of the lowest index is rethrown, so the error a user sees does not
// depend on which thread ran first.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>
#include <exception>
#include <vector>

namespace vrreg::experiments::detail {

/// Calls `task(k)` for k in 0..n-1 in parallel; rethrows the exception of the lowest k that threw.
template <typename Task>
void parallel_tasks(std::size_t n, Task&& task) {
  std::vector<std::exception_ptr> errors(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t k = range.begin(); k < range.end(); ++k) {
                        try {
                          task(k);
                        } catch (...) {
                          errors[k] = std::current_exception();
                        }
                      }
                    });
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace vrreg::experiments::detail
