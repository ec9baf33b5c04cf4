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
