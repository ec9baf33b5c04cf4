// SPDX-License-Identifier: Apache-2.0
// Golden outputs: the commands of tests/data/golden/commands.txt print and write what they did
// before the library was refactored, so a user's numbers never change because the code moved.
// Text must match exactly and numbers to 1e-8 relative: glibc's libm picks its FMA code paths by
// CPU, and the same binary's kriging, RBF and joint-model figures differ in the last bits
// between two machines (measured: at most 4e-10 relative). VRREG_GOLDEN_UPDATE=1 records them
// again (on purpose only).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "two_arm_cell.hpp"
#include "vrreg_test.hpp"

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

// Where a number starts at text[i]: a digit, or a sign or point before one.
bool number_starts(const std::string& text, std::size_t i) {
  const auto digit = [&text](std::size_t k) {
    return k < text.size() && text[k] >= '0' && text[k] <= '9';
  };
  if (digit(i))
    return i == 0 || !(std::isalpha(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_');
  if (text[i] == '.') return digit(i + 1);
  if (text[i] == '-' || text[i] == '+') {
    return digit(i + 1) || (i + 1 < text.size() && text[i + 1] == '.' && digit(i + 2));
  }
  return false;
}

// `actual` equals `expected` but for numbers within 1e-8 relative (1e-9 absolute), or the
// first difference.
std::string golden_difference(const std::string& actual, const std::string& expected) {
  std::size_t i = 0, j = 0;
  while (i < actual.size() && j < expected.size()) {
    if (number_starts(actual, i) && number_starts(expected, j)) {
      char* end_a = nullptr;
      char* end_b = nullptr;
      const double a = std::strtod(actual.c_str() + i, &end_a);
      const double b = std::strtod(expected.c_str() + j, &end_b);
      if (std::abs(a - b) > 1e-8 * std::max(std::abs(a), std::abs(b)) + 1e-9) {
        return "at byte " + std::to_string(i) + ": " +
               std::string(actual.c_str() + i, static_cast<const char*>(end_a)) + " vs " +
               std::string(expected.c_str() + j, static_cast<const char*>(end_b));
      }
      i = static_cast<std::size_t>(end_a - actual.c_str());
      j = static_cast<std::size_t>(end_b - expected.c_str());
      continue;
    }
    if (actual[i] != expected[j]) {
      return "at byte " + std::to_string(i) + ": '" + actual.substr(i, 40) + "' vs '" +
             expected.substr(j, 40) + "'";
    }
    ++i;
    ++j;
  }
  if (i != actual.size() || j != expected.size()) return "lengths differ";
  return "";
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

// Runs the commands of `commands_file` in order in one fresh directory holding cell.csv (the example
// cell) and arms.csv, and compares what each printed and wrote with the recorded goldens.
void check_golden_commands(const std::string& commands_file, const std::string& dir_name) {
  const fs::path golden = fs::path(VRREG_TEST_DATA_DIR) / "golden";
  const bool update = std::getenv("VRREG_GOLDEN_UPDATE") != nullptr;
  const fs::path dir = fresh_dir(dir_name);
  fs::copy_file(fs::path(VRREG_SOURCE_DIR) / "examples/data/example-cell.csv", dir / "cell.csv");
  write_text(dir / "arms.csv", two_arm_cell_csv());
  // A model file of version 1 (millimetres), as register wrote it before version 2: still read,
  // and corrected with the same numbers as then, except rbf and auto's rbf row, which now model
  // the corrections' robot-frame components (the same wherever the tracker stands).
  fs::copy_file(golden / "v1-model.json", dir / "model-v1.json");
  // The report inlines the charting library; a small stand-in keeps this test independent of it.
  write_text(dir / "plotly.js", "/* Plotly stand-in for the golden test */" + std::string(1000, ' '));
  const std::vector<GoldenCommand> commands = read_commands(golden / commands_file);
  ASSERT_GE(commands.size(), 10u);
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
      EXPECT_EQ(golden_difference(text, read_text(golden / golden_name)), "")
          << golden_name << " differs";
    }
  }
  fs::remove_all(dir);
}

TEST(Golden, CommandsPrintAndWriteWhatTheyDidBefore) {
  check_golden_commands("commands.txt", "golden");
}

// The field models: kriging's hyperparameter search takes minutes under the sanitizers.
TEST(Golden, FieldModelCommandsPrintAndWriteWhatTheyDidBefore) {
  if (sanitized()) GTEST_SKIP() << "kriging and the joint model: release build only";
  check_golden_commands("field-commands.txt", "golden-field");
}

// Every method on the simulated test beds (reproduce --beyond): a few minutes, release only.
TEST(Golden, ReproduceBeyondPrintsWhatItDidBefore) {
  if (sanitized()) GTEST_SKIP() << "every field model on every dataset: release build only";
  const fs::path golden = fs::path(VRREG_TEST_DATA_DIR) / "golden" / "reproduce_beyond_json.out";
  const fs::path dir = fresh_dir("golden-beyond");
  const CliResult r = run_vrreg_in(dir, "reproduce --seed 1 --beyond --json --quiet --out ''");
  ASSERT_EQ(r.status, 0) << r.err;
  if (std::getenv("VRREG_GOLDEN_UPDATE") != nullptr) {
    write_text(golden, r.out);
  } else {
    EXPECT_EQ(golden_difference(r.out, read_text(golden)), "") << golden << " differs";
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
