// SPDX-License-Identifier: Apache-2.0
#include "progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

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

namespace {

// The library's stages as the terminal shows them: the most recently reported one that has not
// ended, redrawn by a ticker so that a stage without steps (a model's fit) still shows its time.
class TerminalProgress {
 public:
  void report(std::string_view stage, std::int64_t done, std::int64_t total, double seconds) {
    // A step that finds the line busy is skipped (the next one or the ticker draws), except a
    // stage's start and end.
    std::unique_lock<std::mutex> lock(mutex_, std::defer_lock);
    if (done == 0 || done >= total) {
      lock.lock();
    } else if (!lock.try_lock()) {
      return;
    }
    const auto now = std::chrono::steady_clock::now();
    const std::string name(stage);
    if (done >= total) {
      std::erase_if(active_, [&](const Stage& s) { return s.name == name; });
      if (active_.empty() && shown_) {
        std::fprintf(stderr, "\r%78s\r", "");
        std::fflush(stderr);
        shown_ = false;
      }
      return;
    }
    const auto start = now - std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                 std::chrono::duration<double>(seconds));
    auto it = std::find_if(active_.begin(), active_.end(),
                           [&](const Stage& s) { return s.name == name; });
    if (it == active_.end()) {
      active_.push_back({name, done, total, start});
    } else {
      it->done = done;
      it->total = total;
      Stage moved = *it;  // the latest reported is drawn: last in the list
      active_.erase(it);
      active_.push_back(moved);
    }
    if (!shown_ || now - drawn_ >= std::chrono::milliseconds(100)) draw(now);
  }

  // Redraws the current stage every 200 ms while one runs (a detached thread: the process's end
  // ends it).
  void tick() {
    for (;;) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!active_.empty()) draw(std::chrono::steady_clock::now());
    }
  }

 private:
  struct Stage {
    std::string name;
    std::int64_t done;
    std::int64_t total;
    std::chrono::steady_clock::time_point start;
  };

  // Draws the latest stage once it has run 1 s (quick commands never flash a bar).
  void draw(std::chrono::steady_clock::time_point now) {
    const Stage& s = active_.back();
    const double seconds = std::chrono::duration<double>(now - s.start).count();
    if (seconds < 1.0) return;
    constexpr int kWidth = 20;
    const double fraction = static_cast<double>(s.done) / static_cast<double>(s.total);
    const int filled = static_cast<int>(std::lround(fraction * kWidth));
    std::fprintf(stderr, "\r  %-40.40s [%s%s] %3.0f %% %5.0f s", s.name.c_str(),
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '-').c_str(),
                 100.0 * fraction, seconds);
    std::fflush(stderr);
    drawn_ = now;
    shown_ = true;
  }

  std::mutex mutex_;
  std::vector<Stage> active_;
  std::chrono::steady_clock::time_point drawn_;
  bool shown_ = false;
};

}  // namespace

void install_terminal_progress() {
  if (isatty(STDERR_FILENO) != 1) return;
  static TerminalProgress progress;  // outlives every stage and the ticker
  set_progress_sink([](std::string_view stage, std::int64_t done, std::int64_t total,
                       double seconds) { progress.report(stage, done, total, seconds); });
  std::thread([] { progress.tick(); }).detach();
}

}  // namespace vrreg::cli
