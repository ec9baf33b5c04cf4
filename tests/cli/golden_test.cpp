// SPDX-License-Identifier: Apache-2.0
// Golden outputs: the commands of tests/data/golden/commands.txt print and write exactly
// what they did before the library was refactored, so a user's numbers never change because the
// code moved. VRREG_GOLDEN_UPDATE=1 records them again (on purpose only).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "two_arm_cell.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

struct GoldenCommand {
  std::string name;
  std::string args;
  std::vector<std::string> files;
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<GoldenCommand> read_commands(const fs::path& path) {
  std::ifstream in(path);
  std::vector<GoldenCommand> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto a = line.find('|');
    const auto b = line.find('|', a + 1);
    GoldenCommand c{trim(line.substr(0, a)), trim(line.substr(a + 1, b - a - 1)), {}};
    std::istringstream files(line.substr(b + 1));
    for (std::string f; files >> f;) c.files.push_back(f);
    out.push_back(c);
  }
  return out;
}

TEST(Golden, CommandsPrintAndWriteWhatTheyDidBefore) {
  const fs::path golden = fs::path(VRREG_TEST_DATA_DIR) / "golden";
  const bool update = std::getenv("VRREG_GOLDEN_UPDATE") != nullptr;
  const fs::path dir = fresh_dir("golden");
  fs::copy_file(fs::path(VRREG_SOURCE_DIR) / "examples/data/example-cell.csv", dir / "cell.csv");
  write_text(dir / "arms.csv", two_arm_cell_csv());
  // The report inlines the charting library; a small stand-in keeps this test independent of it.
  write_text(dir / "plotly.js", "/* Plotly stand-in for the golden test */" + std::string(1000, ' '));
  const std::vector<GoldenCommand> commands = read_commands(golden / "commands.txt");
  ASSERT_GE(commands.size(), 20u);
  for (const GoldenCommand& c : commands) {
    SCOPED_TRACE(c.name + ": vrreg " + c.args);
    const CliResult r = run_vrreg_in(dir, c.args, "VRREG_PLOTLY_JS=plotly.js");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::pair<std::string, std::string>> outputs = {{c.name + ".out", r.out}};
    for (const std::string& f : c.files) outputs.emplace_back(c.name + "." + f, read_text(dir / f));
    for (const auto& [golden_name, text] : outputs) {
      if (update) {
        write_text(golden / golden_name, text);
        continue;
      }
      ASSERT_TRUE(fs::exists(golden / golden_name)) << golden_name << " was never recorded";
      EXPECT_EQ(text, read_text(golden / golden_name)) << golden_name << " differs";
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
