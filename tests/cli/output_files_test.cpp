// SPDX-License-Identifier: Apache-2.0
// How the commands treat what is at an output path and odd inputs: only regular files are
// replaced (a device, FIFO or directory is refused and kept), symbolic links are written through,
// permissions are kept, read-only files refused; a FIFO input fails at once; a 255-byte name
// works; an empty name, a negative seed are refused; SIGTERM leaves no temporary file.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

mode_t mode_of(const fs::path& path) {
  struct stat st {};
  ::stat(path.c_str(), &st);
  return st.st_mode & 07777;
}

class OutputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    meas_ = dir_ / "meas.csv";
    ASSERT_EQ(run_vrreg("simulate ur5 A1 -o " + shell_quoted(meas_)).status, 0);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliResult register_to(const fs::path& out) {
    return run_vrreg("register --fiducials " + shell_quoted(meas_) + " -o " + shell_quoted(out));
  }
  // Exit 1, one line naming `out` with `words`.
  static void expect_refused(const CliResult& r, const fs::path& out, const std::string& words) {
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(out.string() + ": " + words), std::string::npos) << r.err;
  }

  fs::path dir_;
  fs::path meas_;
};

TEST_F(OutputFiles, DeviceIsRefusedAndKept) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod of a character device needs root";
  for (const unsigned minor : {3u, 7u}) {  // copies of /dev/null and /dev/full, made here
    const fs::path dev = dir_ / ("dev" + std::to_string(minor));
    ASSERT_EQ(::mknod(dev.c_str(), S_IFCHR | 0666, makedev(1, minor)), 0);
    expect_refused(register_to(dev), dev, "is a device, not a regular file");
    EXPECT_TRUE(fs::is_character_file(dev));
  }
}

TEST_F(OutputFiles, FifoAndDirectoryAreRefusedAndKept) {
  const fs::path fifo = dir_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  expect_refused(register_to(fifo), fifo, "is a FIFO, not a regular file");
  EXPECT_TRUE(fs::is_fifo(fifo));
  fs::create_directory(dir_ / "d");
  expect_refused(register_to(dir_ / "d"), dir_ / "d", "is a directory");
  EXPECT_TRUE(fs::is_directory(dir_ / "d"));
}

TEST_F(OutputFiles, SymlinkIsWrittenThrough) {
  write_text(dir_ / "model.json", "old");
  fs::create_symlink("model.json", dir_ / "link.json");
  const CliResult r = register_to(dir_ / "link.json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
  EXPECT_NE(read_text(dir_ / "model.json"), "old");
  EXPECT_EQ(read_text(dir_ / "model.json").front(), '{');
}

TEST_F(OutputFiles, PermissionsAreKeptAndReadOnlyIsRefused) {
  // As root the read-only case is decided by the mode bits (tests/io runs it as a user too).
  const fs::path mine = dir_ / "mine.json";
  write_text(mine, "old");
  ::chmod(mine.c_str(), 0600);
  ASSERT_EQ(register_to(mine).status, 0);
  EXPECT_EQ(mode_of(mine), 0600u);
  const fs::path ro = dir_ / "ro.json";
  write_text(ro, "keep");
  ::chmod(ro.c_str(), 0444);
  expect_refused(register_to(ro), ro, "is read-only");
  EXPECT_EQ(read_text(ro), "keep");
}

TEST_F(OutputFiles, LongestLegalNameWorks) {
  const fs::path out = dir_ / std::string(255, 'm');
  ASSERT_EQ(register_to(out).status, 0);
  EXPECT_TRUE(fs::is_regular_file(out));
}

TEST_F(OutputFiles, EmptyOutputNameIsRefused) {
  const std::string m = shell_quoted(meas_);
  for (const std::string& args : std::vector<std::string>{
           "register --fiducials " + m + " -o ''", "simulate ur5 A1 -o ''",
           "simulate ur5 --write-errors ''", "correct --model x --points " + m + " -o ''",
           "evaluate --model x --targets " + m + " --per-target ''",
           "report --model x --targets " + m + " -o ''", "plan --parts " + m + " --robot ur5 -o ''",
           "calibrate-testbeds -o ''"}) {
    const CliResult r = run_vrreg_in(dir_, args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_NE(r.err.find("needs a file name"), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(OutputFiles, NegativeSeedsAreRefused) {
  for (const std::string& args : std::vector<std::string>{
           "simulate ur5 A1 --seed -1 -o " + shell_quoted(dir_ / "s.csv"),
           "reproduce --seed -1 --out ''",
           "register --fiducials " + shell_quoted(meas_) + " --strategy 3 --seed -1",
           "calibrate-testbeds --seeds -1", "calibrate-testbeds --seeds 3--1"}) {
    const CliResult r = run_vrreg(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_NE(r.err.find("seed"), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
  }
  EXPECT_FALSE(fs::exists(dir_ / "s.csv"));
}

TEST_F(OutputFiles, FifoInputFailsAtOnce) {
  const fs::path fifo = dir_ / "in.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  for (const std::string& args :
       {"register --fiducials " + shell_quoted(fifo),
        "evaluate --model " + shell_quoted(fifo) + " --targets " + shell_quoted(meas_),
        "plan --parts " + shell_quoted(fifo) + " --robot ur5 --halfwidth-mm 10 --spacing-mm 5",
        "simulate ur5 A1 -o " + shell_quoted(dir_ / "x.csv") + " --errors " + shell_quoted(fifo)}) {
    const CliResult r = run_vrreg_in({}, args, "timeout 20");
    EXPECT_EQ(r.status, 1) << args << " (124: it blocked)";
    EXPECT_NE(r.err.find(fifo.string() + ": is a FIFO, not a regular file"), std::string::npos)
        << r.err;
  }
}

bool has_temporary(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().filename().string().starts_with(".vrreg-")) return true;
  }
  return false;
}

// Watches DIR for a temporary file, stops the command while one exists, then sends SIGTERM: the
// signal lands during a write whatever the timing, or the attempt is repeated.
TEST_F(OutputFiles, SigtermDuringAWriteLeavesNoTemporaryFile) {
  const fs::path out = dir_ / "rep";
  fs::create_directories(out);
  bool caught = false;
  for (int attempt = 0; attempt < 20 && !caught; ++attempt) {
    const int watch = ::inotify_init1(IN_CLOEXEC);
    ASSERT_GE(watch, 0);
    ASSERT_GE(::inotify_add_watch(watch, out.c_str(), IN_CREATE), 0);
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::close(watch);
      const fs::path log = dir_ / "log";
      if (!std::freopen(log.c_str(), "w", stdout) || !std::freopen(log.c_str(), "w", stderr)) {
        ::_exit(3);
      }
      ::execl(VRREG_CLI_PATH, "vrreg", "reproduce", "--seeds", "1", "--only", "lwr4", "--quiet",
              "--no-report", "--out", out.c_str(), static_cast<char*>(nullptr));
      ::_exit(4);
    }
    alignas(inotify_event) char buffer[4096];
    int status = 0;
    bool ended = false;
    while (!caught && !ended) {
      pollfd ready{watch, POLLIN, 0};
      const ssize_t n = ::poll(&ready, 1, 100) > 0 ? ::read(watch, buffer, sizeof buffer) : 0;
      for (char* p = buffer; p < buffer + n && !caught && !ended;) {
        const auto* event = reinterpret_cast<const inotify_event*>(p);
        p += sizeof(inotify_event) + event->len;
        if (event->len == 0 || !std::string(event->name).starts_with(".vrreg-")) continue;
        ::kill(pid, SIGSTOP);
        ASSERT_EQ(::waitpid(pid, &status, WUNTRACED), pid);
        if (!WIFSTOPPED(status)) {
          ended = true;  // finished before the stop
        } else {
          caught = has_temporary(out);  // stopped in the middle of a write
          if (caught) ::kill(pid, SIGTERM);
          ::kill(pid, SIGCONT);
        }
      }
      if (!caught && !ended && ::waitpid(pid, &status, WNOHANG) == pid) ended = true;
    }
    ::close(watch);
    if (!ended) {
      ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    }
    if (caught) {
      EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
      EXPECT_FALSE(has_temporary(out));
    }
  }
  if (!caught) GTEST_SKIP() << "no write was caught in progress in 20 runs (fast disk)";
}

}  // namespace
}  // namespace vrreg::testing
