// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/progress.hpp"

#include <gtest/gtest.h>

#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrreg {
namespace {

struct Report {
  std::string stage;
  std::int64_t done;
  std::int64_t total;
};

// The sink installed for one test, removed at its end.
class Recorder {
 public:
  Recorder() {
    set_progress_sink([this](std::string_view stage, std::int64_t done, std::int64_t total,
                             double seconds) {
      EXPECT_GE(seconds, 0.0);
      const std::lock_guard<std::mutex> lock(mutex_);
      reports_.push_back({std::string(stage), done, total});
    });
  }
  ~Recorder() { set_progress_sink({}); }
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;
  std::vector<Report> reports() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return reports_;
  }

 private:
  std::mutex mutex_;
  std::vector<Report> reports_;
};

TEST(Progress, AStageReportsItsStepsAndEndsAtItsTotal) {
  Recorder recorder;
  {
    ProgressStage stage("fitting", 3);
    stage.advance();
    stage.advance(5);  // past the total: held below it until the stage ends
  }
  const std::vector<Report> r = recorder.reports();
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0].stage, "fitting");
  EXPECT_EQ(r[0].done, 0);
  EXPECT_EQ(r[1].done, 1);
  EXPECT_EQ(r[2].done, 2);
  EXPECT_EQ(r[3].done, 3);
  EXPECT_EQ(r[3].total, 3);
}

TEST(Progress, AnExceptionEndsTheStage) {
  Recorder recorder;
  try {
    ProgressStage stage("reading", 10);
    throw std::runtime_error("bad row");
  } catch (const std::runtime_error&) {
  }
  const std::vector<Report> r = recorder.reports();
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.back().done, r.back().total);
}

TEST(Progress, WithoutASinkNothingIsCalled) {
  set_progress_sink({});
  ProgressStage stage("quiet", 0);  // a total below 1 counts as 1
  stage.advance();
  const ProgressSink previous = set_progress_sink({});
  EXPECT_FALSE(previous);
}

}  // namespace
}  // namespace vrreg
