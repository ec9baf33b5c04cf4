// SPDX-License-Identifier: Apache-2.0
#include "progress_bar.hpp"

#include <unistd.h>

#include <cmath>
#include <memory>
#include <cstdio>
#include <string>

#include "vrreg/core/progress.hpp"

namespace vrreg::cli {

ProgressBar::ProgressBar(int total, bool enabled)
    : total_(total > 0 ? total : 1),
      enabled_(enabled && isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {
  if (enabled_) draw();
}

void ProgressBar::step() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (done_ < total_) ++done_;
  if (enabled_) draw();
}

void ProgressBar::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!enabled_) return;
  std::fprintf(stderr, "\r%70s\r", "");
  std::fflush(stderr);
  enabled_ = false;
}

void ProgressBar::draw() {
  constexpr int kWidth = 30;
  const double fraction = static_cast<double>(done_) / static_cast<double>(total_);
  const int filled = static_cast<int>(std::lround(fraction * kWidth));
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string left = "estimating time left";
  if (done_ > 0) {
    const double remaining = elapsed / done_ * (total_ - done_);
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "about %.0f s left", std::ceil(remaining));
    left = buffer;
  }
  std::fprintf(stderr, "\r  [%s%s] %3.0f %%  %-24s",
               std::string(static_cast<std::size_t>(filled), '#').c_str(),
               std::string(static_cast<std::size_t>(kWidth - filled), '-').c_str(),
               100.0 * fraction, left.c_str());
  std::fflush(stderr);
}

void install_terminal_progress() {
  if (isatty(STDERR_FILENO) != 1) return;
  struct Line {
    std::mutex mutex;
    std::chrono::steady_clock::time_point drawn;
    bool shown = false;
  };
  auto line = std::make_shared<Line>();
  set_progress_sink([line](std::string_view stage, std::int64_t done, std::int64_t total,
                           double seconds) {
    const bool ended = done >= total;
    // A step that finds the line busy is skipped (the next one draws), except a stage's end.
    std::unique_lock<std::mutex> lock(line->mutex, std::defer_lock);
    if (ended) {
      lock.lock();
    } else if (!lock.try_lock()) {
      return;
    }
    if (ended) {
      if (line->shown) std::fprintf(stderr, "\r%78s\r", "");
      line->shown = false;
      std::fflush(stderr);
      return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (seconds < 1.0 || (line->shown && now - line->drawn < std::chrono::milliseconds(100)))
      return;
    constexpr int kWidth = 20;
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    const int filled = static_cast<int>(std::lround(fraction * kWidth));
    std::fprintf(stderr, "\r  %-40.40s [%s%s] %3.0f %% %5.0f s", std::string(stage).c_str(),
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '-').c_str(),
                 100.0 * fraction, seconds);
    std::fflush(stderr);
    line->drawn = now;
    line->shown = true;
  });
}

}  // namespace vrreg::cli
