// SPDX-License-Identifier: Apache-2.0
#include "progress_bar.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

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

}  // namespace vrreg::cli
