// SPDX-License-Identifier: Apache-2.0
#include "experiments/parallel_tasks.hpp"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

namespace vrreg::experiments::detail {
namespace {

// A task that throws must not cut short the parallel loops nested in the others: with a plain
// tbb::parallel_for over the tasks, the throw cancels the group and a nested loop that starts
// after it runs none or part of its iterations, silently.
TEST(ParallelTasks, AThrowingTaskLeavesTheOthersNestedLoopsWhole) {
  std::atomic<bool> thrown{false};
  std::atomic<int> nested_done{0};
  constexpr int kNested = 2000;
  EXPECT_THROW(parallel_tasks(2,
                              [&](std::size_t k) {
                                if (k == 0) {
                                  thrown = true;
                                  throw std::runtime_error("task 0");
                                }
                                // Start the nested loop after task 0 threw (when both run at
                                // once; one thread runs task 0 first or gives up waiting).
                                for (int i = 0; i < 200 && !thrown; ++i)
                                  std::this_thread::sleep_for(std::chrono::milliseconds(5));
                                std::this_thread::sleep_for(std::chrono::milliseconds(20));
                                tbb::parallel_for(0, kNested, [&](int) { ++nested_done; });
                              }),
               std::runtime_error);
  EXPECT_EQ(nested_done.load(), kNested);
}

TEST(ParallelTasks, RethrowsTheLowestIndexThatThrew) {
  for (int repeat = 0; repeat < 20; ++repeat) {
    try {
      parallel_tasks(8, [](std::size_t k) {
        if (k % 3 == 2) throw std::runtime_error("task " + std::to_string(k));
      });
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "task 2");
    }
  }
}

TEST(ParallelTasks, RunsEveryTaskOnce) {
  std::vector<std::atomic<int>> runs(100);
  parallel_tasks(runs.size(), [&](std::size_t k) { ++runs[k]; });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
}

}  // namespace
}  // namespace vrreg::experiments::detail
