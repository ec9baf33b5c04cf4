// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/progress.hpp"

#include <algorithm>
#include <memory>
#include <mutex>
#include <utility>

namespace vrreg {
namespace {

// The sink is read on every step from any thread and replaced rarely: a shared pointer copied
// under a lock keeps a running stage's sink alive while another is installed.
struct SinkSlot {
  std::mutex mutex;
  std::shared_ptr<const ProgressSink> sink;
};

SinkSlot& sink_slot() {
  static SinkSlot slot;
  return slot;
}

std::shared_ptr<const ProgressSink> current_sink() {
  SinkSlot& slot = sink_slot();
  const std::lock_guard<std::mutex> lock(slot.mutex);
  return slot.sink;
}

void report(std::string_view name, std::int64_t done, std::int64_t total,
            std::chrono::steady_clock::time_point start) {
  const std::shared_ptr<const ProgressSink> sink = current_sink();
  if (!sink || !*sink) return;
  (*sink)(name, done, total,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace

ProgressSink set_progress_sink(ProgressSink sink) {
  std::shared_ptr<const ProgressSink> next =
      sink ? std::make_shared<const ProgressSink>(std::move(sink)) : nullptr;
  SinkSlot& slot = sink_slot();
  const std::lock_guard<std::mutex> lock(slot.mutex);
  std::shared_ptr<const ProgressSink> previous = std::exchange(slot.sink, std::move(next));
  return previous ? *previous : ProgressSink{};
}

ProgressStage::ProgressStage(std::string name, std::int64_t total)
    : name_(std::move(name)),
      total_(std::max<std::int64_t>(total, 1)),
      start_(std::chrono::steady_clock::now()),
      active_(current_sink() != nullptr) {
  if (active_) report(name_, 0, total_, start_);
}

ProgressStage::~ProgressStage() {
  if (active_) report(name_, total_, total_, start_);
}

void ProgressStage::advance(std::int64_t steps) {
  if (!active_) return;
  const std::int64_t done = std::min(done_.fetch_add(steps, std::memory_order_relaxed) + steps,
                                     total_ - 1);  // total only at the end
  report(name_, done, total_, start_);
}

}  // namespace vrreg
