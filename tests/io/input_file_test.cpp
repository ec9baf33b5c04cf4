// SPDX-License-Identifier: Apache-2.0
// Readers take regular files only: a FIFO, device or directory is refused before it is opened,
// so a FIFO with no writer cannot block them.
#include "vrreg/io/input_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include "as_user.hpp"
#include "io_test_helpers.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/parts_csv.hpp"
#include "vrreg/io/plan_csv.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

// A blocked open would hang the test: SIGALRM ends it instead.
class InputFile : public ::testing::Test {
 protected:
  void SetUp() override { ::alarm(30); }
  void TearDown() override { ::alarm(0); }
};

TEST_F(InputFile, FifoIsRefusedWithoutBlockingByEveryReader) {
  TempDir dir;
  const std::string fifo = dir.file("in.csv");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const char* words = "is a FIFO, not a regular file";
  EXPECT_TRUE(throws_file_error([&] { (void)open_input_file(fifo); }, fifo, 0, words));
  EXPECT_TRUE(throws_file_error([&] { (void)read_input_file(fifo); }, fifo, 0, words));
  EXPECT_TRUE(throws_file_error([&] { (void)read_measurement_csv(fifo); }, fifo, 0, words));
  EXPECT_TRUE(throws_file_error([&] { (void)read_model_json(fifo); }, fifo, 0, words));
  EXPECT_TRUE(throws_file_error([&] { (void)read_plan_csv(fifo); }, fifo, 0, words));
  EXPECT_TRUE(throws_file_error([&] { (void)read_parts_csv(fifo); }, fifo, 0, words));
}

TEST_F(InputFile, DirectoryIsRefused) {
  TempDir dir;
  const std::string path = dir.path().string();
  EXPECT_TRUE(throws_file_error([&] { (void)open_input_file(path); }, path, 0,
                                "is a directory, not a regular file"));
}

TEST_F(InputFile, DeviceIsRefused) {
  if (!vrreg::testing::is_root()) GTEST_SKIP() << "mknod of a character device needs root";
  TempDir dir;
  const std::string path = dir.file("zero-copy");
  ASSERT_EQ(::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 5)), 0);
  EXPECT_TRUE(throws_file_error([&] { (void)read_input_file(path); }, path, 0,
                                "is a device, not a regular file"));
}

TEST_F(InputFile, RegularFileAndSymlinkToOneAreRead) {
  TempDir dir;
  const std::string path = dir.write("in.txt", "abc");
  std::filesystem::create_symlink(path, dir.file("link.txt"));
  EXPECT_EQ(read_input_file(path), "abc");
  EXPECT_EQ(read_input_file(dir.file("link.txt")), "abc");
  EXPECT_TRUE(throws_file_error([&] { (void)read_input_file(dir.file("none")); }, dir.file("none"),
                                0, "cannot open: No such file or directory"));
}

TEST_F(InputFile, EveryByteOfALargeOrEmptyFileIsRead) {
  TempDir dir;
  std::string bytes;
  for (int i = 0; i < 200001; ++i) bytes.push_back(static_cast<char>((i * 7919) % 256));
  EXPECT_EQ(read_input_file(dir.write("big.bin", bytes)), bytes);
  EXPECT_EQ(read_input_file(dir.write("empty.txt", "")), "");
}

}  // namespace
}  // namespace vrreg::io
