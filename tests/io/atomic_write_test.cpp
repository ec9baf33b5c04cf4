// SPDX-License-Identifier: Apache-2.0
// Output files are written whole or not at all.
#include "vrreg/io/atomic_write.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io_test_helpers.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::directory_entries;
using vrreg::testing::read_text;
using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

TEST(AtomicWrite, WritesContentAndLeavesNoTemporaryFile) {
  TempDir dir;
  const std::string path = dir.file("out.txt");
  write_file_atomically(path, "hello\n");
  EXPECT_EQ(read_text(path), "hello\n");
  EXPECT_EQ(directory_entries(dir.path()), 1u);
}

TEST(AtomicWrite, ReplacesAnExistingFileWhole) {
  TempDir dir;
  const std::string path = dir.write("out.txt", std::string(100000, 'x'));
  write_file_atomically(path, "short");
  EXPECT_EQ(read_text(path), "short");
  EXPECT_EQ(directory_entries(dir.path()), 1u);
}

TEST(AtomicWrite, WritesLargeAndEmptyContent) {
  TempDir dir;
  const std::string big(5 * 1024 * 1024 + 7, 'y');
  write_file_atomically(dir.file("big"), big);
  EXPECT_EQ(read_text(dir.file("big")), big);
  write_file_atomically(dir.file("empty"), "");
  EXPECT_EQ(read_text(dir.file("empty")), "");
}

TEST(AtomicWrite, MissingDirectoryThrowsAndLeavesNothing) {
  TempDir dir;
  const std::string path = dir.file("no/such/dir/out.txt");
  EXPECT_TRUE(throws_file_error([&] { write_file_atomically(path, "x"); }, path, 0,
                                "cannot create a temporary file"));
  EXPECT_EQ(directory_entries(dir.path()), 0u);
}

TEST(AtomicWrite, DirectoryAsTargetThrowsAndKeepsIt) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "sub");
  const std::string path = dir.file("sub");
  EXPECT_TRUE(
      throws_file_error([&] { write_file_atomically(path, "x"); }, path, 0, "is a directory"));
  EXPECT_TRUE(std::filesystem::is_directory(path));
  EXPECT_EQ(directory_entries(dir.path()), 1u);
}

TEST(AtomicWrite, ParentThatIsAFileThrowsAndLeavesItAlone) {
  TempDir dir;
  const std::string parent = dir.write("file", "keep");
  const std::string path = parent + "/out.txt";
  EXPECT_THROW(write_file_atomically(path, "x"), FileError);
  EXPECT_EQ(read_text(parent), "keep");
  EXPECT_EQ(directory_entries(dir.path()), 1u);
}

}  // namespace
}  // namespace vrreg::io
