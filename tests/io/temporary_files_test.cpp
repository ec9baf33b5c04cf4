// SPDX-License-Identifier: Apache-2.0
// The signal handler of remove_temporary_files_on_signal: a temporary file being written is
// removed on SIGTERM and SIGINT, and the process still ends by the signal.
#include "io/temporary_files.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "io_test_helpers.hpp"
#include "vrreg/io/atomic_write.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;

// A child lists a temporary file as write_file_atomically does, says so through a pipe and waits;
// the signal arrives only then, so the test does not depend on timing.
void expect_removed_on(int signal_number) {
  TempDir dir;
  const std::string temporary = dir.write(".vrreg-abc123", "partial");
  const std::string other = dir.write("keep.csv", "not ours");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    remove_temporary_files_on_signal();
    detail::remember_temporary(temporary);
    const char byte = 'r';
    if (::write(ready[1], &byte, 1) != 1) ::_exit(3);
    for (;;) ::pause();
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  ::close(ready[0]);
  ::close(ready[1]);
  ASSERT_EQ(::kill(pid, signal_number), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << status;
  EXPECT_FALSE(std::filesystem::exists(temporary));
  EXPECT_TRUE(std::filesystem::exists(other));
}

TEST(TemporaryFiles, RemovedOnSigterm) { expect_removed_on(SIGTERM); }
TEST(TemporaryFiles, RemovedOnSigint) { expect_removed_on(SIGINT); }

TEST(TemporaryFiles, ForgottenFilesAreLeftAlone) {
  TempDir dir;
  const std::string done = dir.write("renamed-away", "x");
  const pid_t pid = ::fork();
  if (pid == 0) {
    remove_temporary_files_on_signal();
    detail::forget_temporary(detail::remember_temporary(done));
    ::raise(SIGTERM);
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_TRUE(std::filesystem::exists(done));
}

}  // namespace
}  // namespace vrreg::io
