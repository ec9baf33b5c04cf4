// SPDX-License-Identifier: Apache-2.0
// Hostile robot and error-model documents: deep nesting, YAML alias bombs, numbers
// beyond a double and invalid UTF-8 end in one FileError naming the file, never a crash, a runaway
// or a raw library message.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "io_test_helpers.hpp"
#include "vrreg/io/json_text.hpp"
#include "vrreg/robot_io/error_model_file.hpp"
#include "vrreg/robot_io/robot_file.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

// 65 000 levels of lists: 130 KB that once overflowed the stack.
std::string deep_json() { return std::string(65000, '[') + std::string(65000, ']'); }

// "Billion laughs": nine levels of nine aliases, 9^9 values from a few hundred bytes.
std::string alias_bomb_yaml() {
  std::string text = "a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n";
  for (int level = 1; level <= 9; ++level) {
    const std::string prev = "*a" + std::to_string(level - 1);
    text += "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [";
    for (int k = 0; k < 9; ++k) text += (k ? ", " : "") + prev;
    text += "]\n";
  }
  return text;
}

// `action` throws one FileError naming `path` (any line) whose message holds `fragment`.
::testing::AssertionResult names_file(const std::function<void()>& action, const std::string& path,
                                      const std::string& fragment) {
  try {
    action();
  } catch (const FileError& e) {
    const std::string what = e.what();
    if (e.path() != path || what.find(fragment) == std::string::npos ||
        what.find('\n') != std::string::npos) {
      return ::testing::AssertionFailure() << "got: " << what;
    }
    return ::testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another exception: " << e.what();
  }
  return ::testing::AssertionFailure() << "did not throw";
}

TEST(HostileDocument, RobotFilesEndInOneFileError) {
  TempDir dir;
  const auto check = [&](const std::string& name, const std::string& text, std::size_t line,
                         const std::string& fragment) {
    const std::string path = dir.write(name, text);
    EXPECT_TRUE(throws_file_error([&] { (void)read_robot_file(path); }, path, line, fragment));
  };
  check("deep.json", deep_json(), 1, "nested deeper than 64 levels");
  check("deep.yaml", "dh: " + std::string(100, '[') + std::string(100, ']') + "\n", 1,
        "nested deeper than 64 levels");
  check("overflow.json", "{\"dh\": [{\"a_m\": 1e400, \"alpha_deg\": 0, \"d_m\": 0}]}", 0,
        "invalid JSON: number overflow");
  const std::string bomb = dir.write("bomb.yaml", alias_bomb_yaml());
  EXPECT_TRUE(names_file([&] { (void)read_robot_file(bomb); }, bomb, "more than 100000 values"));
  // Invalid UTF-8 in a value that a message quotes: the message is written, bytes replaced.
  check("utf8.yaml", "dh: \"\xff\xfe\"\n", 1, "dh: expected");
}

TEST(HostileDocument, ErrorModelFilesEndInOneFileError) {
  TempDir dir;
  const simulation::Testbed testbed = simulation::ur5_testbed();
  const auto check = [&](const std::string& name, const std::string& text,
                         const std::string& fragment) {
    const std::string path = dir.write(name, text);
    EXPECT_TRUE(names_file([&] { (void)read_error_model_file(path, testbed); }, path, fragment));
  };
  check("deep.json", deep_json(), "nested deeper than 64 levels");
  check("bomb.yaml", alias_bomb_yaml(), "more than 100000 values");
}

TEST(HostileDocument, MessagesQuoteValuesBriefly) {
  EXPECT_EQ(quote_value(nlohmann::json(1.5)), "1.5");
  EXPECT_EQ(quote_value(nlohmann::json("ur5")), "\"ur5\"");
  const std::string long_text(500, 'x');
  EXPECT_EQ(quote_value(nlohmann::json(long_text)).size(), 60u);
  EXPECT_EQ(quote_value(nlohmann::json(std::vector<int>(1000, 7))), "a list of 1000 values");
  EXPECT_EQ(quote_value(nlohmann::json("a\xff"
                                       "b")),
            "\"a\xEF\xBF\xBD"
            "b\"");
}

}  // namespace
}  // namespace vrreg::io
