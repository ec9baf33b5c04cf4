// SPDX-License-Identifier: Apache-2.0
// What write_file_atomically does with what is already at the target: replaces only regular
// files, writes through symbolic links, keeps permission bits, refuses read-only files.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "as_user.hpp"
#include "io_test_helpers.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io {
namespace {

namespace fs = std::filesystem;
using vrreg::testing::directory_entries;
using vrreg::testing::is_root;
using vrreg::testing::read_text;
using vrreg::testing::run_as_nobody;
using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

mode_t mode_of(const std::string& path) {
  struct stat st {};
  ::stat(path.c_str(), &st);
  return st.st_mode & 07777;
}

TEST(AtomicWriteTargets, FifoIsRefusedAndKept) {
  TempDir dir;
  const std::string path = dir.file("fifo");
  ASSERT_EQ(::mkfifo(path.c_str(), 0644), 0);
  EXPECT_TRUE(throws_file_error([&] { write_file_atomically(path, "x"); }, path, 0,
                                "is a FIFO, not a regular file"));
  EXPECT_TRUE(fs::is_fifo(path));
  EXPECT_EQ(directory_entries(dir.path()), 1u);
}

TEST(AtomicWriteTargets, DeviceIsRefusedAndKept) {
  if (!is_root()) GTEST_SKIP() << "mknod of a character device needs root";
  TempDir dir;
  const std::string path = dir.file("null-copy");
  ASSERT_EQ(::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
  EXPECT_TRUE(throws_file_error([&] { write_file_atomically(path, "x"); }, path, 0,
                                "is a device, not a regular file"));
  EXPECT_TRUE(fs::is_character_file(path));
  EXPECT_EQ(directory_entries(dir.path()), 1u);
}

TEST(AtomicWriteTargets, SymlinkIsWrittenThroughAndStays) {
  TempDir dir;
  fs::create_directory(dir.path() / "real");
  const std::string target = dir.write("real/out.txt", "old");
  const std::string link = dir.file("link.txt");
  fs::create_symlink("real/out.txt", link);  // relative: resolved beside the link
  write_file_atomically(link, "new");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_text(target), "new");
  EXPECT_EQ(directory_entries(dir.path() / "real"), 1u);
}

TEST(AtomicWriteTargets, DanglingSymlinkCreatesItsTarget) {
  TempDir dir;
  const std::string link = dir.file("link.txt");
  fs::create_symlink(dir.file("made.txt"), link);
  write_file_atomically(link, "made");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_text(dir.file("made.txt")), "made");
}

TEST(AtomicWriteTargets, PermissionBitsAreKept) {
  TempDir dir;
  for (const mode_t mode : {0600, 0640, 0664}) {
    const std::string path = dir.write("out" + std::to_string(mode), "old");
    ASSERT_EQ(::chmod(path.c_str(), mode), 0);
    write_file_atomically(path, "new");
    EXPECT_EQ(read_text(path), "new");
    EXPECT_EQ(mode_of(path), mode);
  }
}

TEST(AtomicWriteTargets, ReadOnlyFileIsRefused) {
  // As root by the mode bits (root could write it); otherwise by access(W_OK).
  TempDir dir;
  const std::string path = dir.write("ro.txt", "keep");
  ASSERT_EQ(::chmod(path.c_str(), 0444), 0);
  EXPECT_TRUE(
      throws_file_error([&] { write_file_atomically(path, "x"); }, path, 0, "is read-only"));
  EXPECT_EQ(read_text(path), "keep");
  EXPECT_EQ(directory_entries(dir.path()), 1u);
}

TEST(AtomicWriteTargets, AsAUserReadOnlyIsRefusedAndModeKept) {
  if (!is_root())
    GTEST_SKIP() << "needs root to switch to user nobody (the non-root cases above "
                    "already run as this user)";
  TempDir dir;
  ASSERT_EQ(::chmod(dir.path().c_str(), 0777), 0);
  const std::string ro = dir.write("ro.txt", "keep");
  const std::string mine = dir.write("mine.txt", "old");
  for (const auto& [path, mode] : {std::pair{ro, 0444}, std::pair{mine, 0600}}) {
    ASSERT_EQ(::chown(path.c_str(), vrreg::testing::kNobody, vrreg::testing::kNobody), 0);
    ASSERT_EQ(::chmod(path.c_str(), static_cast<mode_t>(mode)), 0);
  }
  EXPECT_TRUE(run_as_nobody([&] {
    try {
      write_file_atomically(ro, "x");
      return false;
    } catch (const FileError& e) {
      return std::string(e.what()).find("is read-only") != std::string::npos;
    }
  }));
  EXPECT_EQ(read_text(ro), "keep");
  EXPECT_TRUE(run_as_nobody([&] {
    write_file_atomically(mine, "new");
    return true;
  }));
  EXPECT_EQ(read_text(mine), "new");
  EXPECT_EQ(mode_of(mine), 0600);
  struct stat st {};
  ASSERT_EQ(::stat(mine.c_str(), &st), 0);
  EXPECT_EQ(st.st_uid, vrreg::testing::kNobody);
  EXPECT_EQ(directory_entries(dir.path()), 2u);
}

TEST(AtomicWriteTargets, OwnerIsKeptAsRoot) {
  if (!is_root()) GTEST_SKIP() << "only root may give a file to another user";
  TempDir dir;
  const std::string path = dir.write("theirs.txt", "old");
  ASSERT_EQ(::chown(path.c_str(), vrreg::testing::kNobody, vrreg::testing::kNobody), 0);
  write_file_atomically(path, "new");
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_uid, vrreg::testing::kNobody);
  EXPECT_EQ(st.st_gid, vrreg::testing::kNobody);
}

TEST(AtomicWriteTargets, LongestLegalNameWorks) {
  TempDir dir;
  const std::string path = dir.file(std::string(255, 'n'));
  write_file_atomically(path, "long");
  EXPECT_EQ(read_text(path), "long");
  EXPECT_EQ(directory_entries(dir.path()), 1u);
}

TEST(AtomicWriteTargets, EmptyPathIsRefused) {
  EXPECT_TRUE(throws_file_error([] { write_file_atomically("", "x"); }, "(empty path)", 0,
                                "no output file name"));
}

}  // namespace
}  // namespace vrreg::io
