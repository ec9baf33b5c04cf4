// SPDX-License-Identifier: Apache-2.0
// Hostile model and reproduce files at the command line: a 65 000-level JSON and a
// number beyond a double end in exit status 1 and one line naming the file.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

TEST(HostileFile, DeepOrOverflowingJsonIsOneLineNamingTheFile) {
  const fs::path dir = fresh_dir("hostile-file");
  const std::string cell = std::string(VRREG_SOURCE_DIR) + "/examples/data/example-cell.csv";
  const std::string deep = (dir / "deep.json").string();
  write_text(deep, std::string(65000, '[') + std::string(65000, ']'));
  const std::string overflow = (dir / "overflow.json").string();
  write_text(overflow, "{\"format\": \"vrreg-model\", \"version\": 1e400}");
  fs::create_directories(dir / "run");
  write_text(dir / "run" / "reproduce.json", std::string(65000, '{'));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"evaluate --model '" + deep + "' --targets '" + cell + "'", deep},
      {"correct --model '" + deep + "' --points '" + cell + "' -o '" + (dir / "c.csv").string() +
           "'",
       deep},
      {"evaluate --model '" + overflow + "' --targets '" + cell + "'", overflow},
      {"report --reproduce '" + (dir / "run").string() + "' -o '" + (dir / "r.html").string() + "'",
       (dir / "run" / "reproduce.json").string()},
  };
  for (const auto& [args, file] : cases) {
    const CliResult r = run_vrreg(args);
    EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "c.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
