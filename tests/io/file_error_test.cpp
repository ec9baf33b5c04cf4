// SPDX-License-Identifier: Apache-2.0
// FileError reads "path:line: message", or "path: message" when there is no line.
#include "vrreg/io/file_error.hpp"

#include <gtest/gtest.h>

namespace vrreg::io {
namespace {

TEST(FileError, NamesFileAndLine) {
  const FileError e("data/f.csv", 12, "short row");
  EXPECT_STREQ(e.what(), "data/f.csv:12: short row");
  EXPECT_EQ(e.path(), "data/f.csv");
  EXPECT_EQ(e.line(), 12u);
}

TEST(FileError, LineZeroMeansNoLine) {
  EXPECT_STREQ(FileError("m.json", 0, "unsupported model version 7").what(),
               "m.json: unsupported model version 7");
}

// Found by fuzzing (tests/fuzz/regressions/robot_file): yaml-cpp quotes the raw byte after a
// backslash in its message, so a message could hold a newline and span two lines.
TEST(FileError, IsAlwaysOneLine) {
  const FileError e("dir\nname.yaml", 3, "unknown escape character: \n\x01\x7f\tend\r");
  EXPECT_STREQ(e.what(), "dir\\nname.yaml:3: unknown escape character: \\n\\x01\\x7f\\tend\\r");
  EXPECT_EQ(e.path(), "dir\nname.yaml");  // the path itself is kept as given
  EXPECT_STREQ(FileError("f", 0, "caf\xC3\xA9").what(), "f: caf\xC3\xA9");  // UTF-8 is kept
}

TEST(FileError, IsAnInputError) {
  try {
    throw FileError("x", 1, "y");
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "x:1: y");
    return;
  }
  FAIL() << "not caught as InputError";
}

}  // namespace
}  // namespace vrreg::io
