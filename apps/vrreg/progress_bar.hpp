// SPDX-License-Identifier: Apache-2.0
#pragma once
// A progress bar on stderr with an estimate of the time left, drawn only when stderr is a
// terminal (never into a file or pipe); step() may be called from several threads.
#include <chrono>
#include <mutex>

namespace vrreg::cli {

class ProgressBar {
 public:
  /// `total` steps; `enabled` false (e.g. --quiet) draws nothing.
  ProgressBar(int total, bool enabled);
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  /// One more step done: redraws the bar.
  void step();
  /// Clears the bar's line (call before printing results).
  void finish();

 private:
  void draw();
  int total_;
  int done_ = 0;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

/// Draws the library's long stages (vrreg/core/progress.hpp) on stderr when it is a terminal
/// (never into a file or pipe): the latest stage shows once it has run 1 s, with its steps and
/// time, redrawn at most 10 times a second (and every 200 ms by a ticker, so a stage without
/// steps still shows); the line is cleared when the last stage ends.
void install_terminal_progress();

}  // namespace vrreg::cli
