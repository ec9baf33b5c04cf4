// SPDX-License-Identifier: Apache-2.0
#pragma once
// Progress of long computations (a large cell's fit and cross-validation take seconds to
// minutes), for a front end to show. The library only counts steps; the program installs a sink
// that draws (the command line: a bar on a terminal). Without a sink a stage costs one lock when
// it begins and nothing per step.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace vrreg {

/// Receives one stage's progress: its name, steps done of total (done == total: it ended), and
/// the seconds since it began. Called from any thread, often: it must be cheap and thread safe.
using ProgressSink =
    std::function<void(std::string_view stage, std::int64_t done, std::int64_t total, double seconds)>;

/// Installs `sink` for the whole process (empty: none) and returns the previous one. Install
/// before, not while, computations run.
ProgressSink set_progress_sink(ProgressSink sink);

/// One stage of a long computation: `total` steps advanced from any thread; its end (also by an
/// exception) reports done == total.
class ProgressStage {
 public:
  ProgressStage(std::string name, std::int64_t total);
  ~ProgressStage();
  ProgressStage(const ProgressStage&) = delete;
  ProgressStage& operator=(const ProgressStage&) = delete;
  void advance(std::int64_t steps = 1);

 private:
  std::string name_{};
  std::int64_t total_{};
  std::atomic<std::int64_t> done_{0};
  std::chrono::steady_clock::time_point start_{};
  bool active_{};
};

}  // namespace vrreg
