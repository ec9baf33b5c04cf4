// SPDX-License-Identifier: Apache-2.0
// An output that is an input of the same command (however it is spelled) is refused.
#include "vrreg/io/output_paths.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "io_test_helpers.hpp"

namespace vrreg::io {
namespace {

namespace fs = std::filesystem;
using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

TEST(OutputPaths, EverySpellingOfTheInputIsRefused) {
  TempDir dir;
  const std::string in = dir.write("x.csv", "data");
  fs::create_directory(dir.path() / "sub");
  fs::create_symlink(in, dir.file("link.csv"));
  fs::create_hard_link(in, dir.file("hard.csv"));
  for (const std::string& out :
       {in, dir.file("sub/../x.csv"), dir.file("link.csv"), dir.file("hard.csv")}) {
    EXPECT_TRUE(throws_file_error(
        [&] {
          check_outputs_are_not_inputs({{"--fiducials", in}}, {{"-o", out}});
        },
        out, 0, "-o is the input --fiducials '" + in + "'"));
  }
}

TEST(OutputPaths, TwoOutputsOfOneNameAreRefused) {
  TempDir dir;
  const std::string out = dir.file("new.csv");  // not there yet
  EXPECT_TRUE(throws_file_error(
      [&] {
        check_outputs_are_not_inputs({}, {{"-o", out}, {"--write-errors", dir.file("./new.csv")}});
      },
      dir.file("./new.csv"), 0, "--write-errors is the same file as -o"));
}

TEST(OutputPaths, OtherFilesAndAbsentOptionsPass) {
  TempDir dir;
  const std::string in = dir.write("x.csv", "data");
  const std::string other = dir.write("y.csv", "data");
  EXPECT_NO_THROW(check_outputs_are_not_inputs({{"--fiducials", in}, {"--plan", ""}},
                                               {{"-o", other}, {"--write-errors", ""}}));
  EXPECT_NO_THROW(check_outputs_are_not_inputs({{"--fiducials", in}}, {{"-o", dir.file("z")}}));
}

}  // namespace
}  // namespace vrreg::io
