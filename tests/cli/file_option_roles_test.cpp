// SPDX-License-Identifier: Apache-2.0
// Every command's options, built in process as main builds them: each option that takes text (so
// could name a file) declares whether the command reads it, writes it or never opens it, so that
// main's one check sees every input and every output. A new command or option without a role
// fails here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "cli_runner.hpp"
#include "cli_support.hpp"
#include "command_registry.hpp"
#include "file_options.hpp"

namespace vrreg::cli {
namespace {

// The commands' options, each with its role when it has one.
struct AllCommands {
  CLI::App app{"vrreg under test", "vrreg"};
  std::vector<CLI::App*> commands;
  AllCommands() {
    for (const CommandEntry& entry : command_registry()) entry.setup(app);
    commands = app.get_subcommands([](CLI::App*) { return true; });
  }
};

AllCommands& all_commands() {
  static AllCommands* all = new AllCommands;  // built once: roles are recorded per option
  return *all;
}

bool takes_text(const CLI::Option& option) {
  return option.get_type_size() != 0 && option.get_type_name().starts_with("TEXT");
}

std::string option_name(const CLI::App& command, const CLI::Option& option) {
  return "vrreg " + command.get_name() + " " + option.get_name();
}

TEST(FileOptionRoles, EveryCommandIsThere) {
  std::set<std::string> names;
  for (const CLI::App* command : all_commands().commands) names.insert(command->get_name());
  for (const char* expected :
       {"register", "evaluate", "correct", "plan", "simulate", "report", "check", "update",
        "calibrate-testbeds", "export", "fk", "ik", "serve", "snippet", "reproduce"}) {
    EXPECT_TRUE(names.contains(expected)) << expected;
  }
}

TEST(FileOptionRoles, EveryTextOptionOfEveryCommandDeclaresItsRole) {
  int text_options = 0;
  for (const CLI::App* command : all_commands().commands) {
    for (const CLI::Option* option : command->get_options()) {
      if (!takes_text(*option)) continue;
      ++text_options;
      EXPECT_TRUE(declared_file_role(option).has_value())
          << option_name(*command, *option)
          << " takes text but declares no role: add it with add_input_option, add_output_option, "
             "add_robot_option, declare_file_role or not_a_file (apps/vrreg/file_options.hpp)";
    }
  }
  EXPECT_GT(text_options, 40);
}

TEST(FileOptionRoles, FileRolesGoWithOptionsThatTakeText) {
  for (const CLI::App* command : all_commands().commands) {
    for (const CLI::Option* option : command->get_options()) {
      if (takes_text(*option)) continue;
      EXPECT_FALSE(declared_file_role(option).has_value()) << option_name(*command, *option);
    }
  }
}

// The files each command reads and writes, as the check sees them.
TEST(FileOptionRoles, InputsAndOutputsOfTheCommands) {
  using enum FileRole;
  const std::map<std::string, std::map<std::string, FileRole>> expected = {
      {"register", {{"--fiducials", kInput}, {"--robot", kInput}, {"--output", kOutput}}},
      {"evaluate",
       {{"--model", kInput},
        {"--targets", kInput},
        {"--robot", kInput},
        {"--per-target", kOutput}}},
      {"correct",
       {{"--model", kInput}, {"--points", kInput}, {"--robot", kInput}, {"--output", kOutput}}},
      {"plan",
       {{"--parts", kInput},
        {"--robot", kInput},
        {"--output", kOutput},
        {"--program", kOutput},
        {"--monitor-program", kOutput}}},
      {"simulate",
       {{"--plan", kInput},
        {"--errors", kInput},
        {"--output", kOutput},
        {"--write-errors", kOutput}}},
      {"report",
       {{"--model", kInput},
        {"--targets", kInput},
        {"--reproduce", kInput},
        {"--history", kInput},
        {"--plan", kInput},
        {"--output", kOutput}}},
      {"check", {{"--model", kInput}, {"--monitor", kInput}, {"--history", kOutput}}},
      {"update",
       {{"--model", kInput}, {"--points", kInput}, {"--history", kInput}, {"--output", kOutput}}},
      {"calibrate-testbeds",
       {{"--ur5-errors", kInput}, {"--lwr4-errors", kInput}, {"--output", kOutput}}},
      {"export", {{"--model", kInput}, {"--output", kOutput}}},
      {"fk", {{"robot", kInput}}},
      {"ik", {{"robot", kInput}}},
      {"serve", {{"--model", kInput}, {"--token-file", kInput}, {"--audit-log", kOutput}}},
      {"snippet",
       {{"--model", kNotAFile},
        {"--model-file", kInput},
        {"--token-file", kInput},
        {"--output", kOutput},
        {"--eki-config", kOutput}}},
      {"reproduce", {{"--out", kOutputDirectory}}},
  };
  for (const CLI::App* command : all_commands().commands) {
    const auto it = expected.find(command->get_name());
    if (it == expected.end()) continue;
    for (const auto& [name, role] : it->second) {
      const CLI::Option* option = command->get_option_no_throw(name);
      ASSERT_NE(option, nullptr) << command->get_name() << " " << name;
      EXPECT_EQ(declared_file_role(option), role) << command->get_name() << " " << name;
    }
    // No other option of the command reads or writes a file.
    for (const CLI::Option* option : command->get_options()) {
      const std::optional<FileRole> role = declared_file_role(option);
      if (!role || *role == kNotAFile) continue;
      bool listed = false;
      for (const auto& entry : it->second) {
        listed = listed || command->get_option_no_throw(entry.first) == option;
      }
      EXPECT_TRUE(listed) << option_name(*command, *option) << " is not in this table";
    }
  }
}

// The check main runs reads each option's files as parsed: a robot's built-in name is no file, a
// directory's input is the file in it, an output directory may hold no input.
TEST(FileOptionRoles, TheCheckSeesEachDeclaredFileAsTheCommandUsesIt) {
  namespace fs = std::filesystem;
  const fs::path dir = vrreg::testing::fresh_dir("file-option-check");
  vrreg::testing::write_text(dir / "in.csv", "x\n");
  fs::create_directories(dir / "rep");
  vrreg::testing::write_text(dir / "rep" / "reproduce.json", "{}\n");
  // Roles are recorded for the process's lifetime (main builds its commands once): each probe
  // command, and the strings its options fill, is kept alive.
  struct Probe {
    CLI::App app{"test", "t"};
    std::string in, robot, rep, out, out_dir;
  };
  static std::vector<std::unique_ptr<Probe>> probes;
  const auto check = [&](const std::vector<std::string>& words) {
    Probe& p = *probes.emplace_back(std::make_unique<Probe>());
    CLI::App* command = p.app.add_subcommand("cmd", "");
    add_input_option(*command, "--in", p.in, "");
    add_robot_option(*command, "--robot", p.robot, "");
    add_input_directory_option(*command, "--reproduce", p.rep, "", "reproduce.json");
    add_output_option(*command, "-o,--output", p.out, "");
    declare_file_role(*command, command->add_option("--out-dir", p.out_dir, ""),
                      FileRole::kOutputDirectory,
                      [&p] { return std::vector<std::string>{p.out_dir}; });
    std::vector<std::string> args(words.rbegin(), words.rend());
    args.push_back("cmd");
    p.app.parse(args);
    check_command_files(*command);
  };
  const std::string in = (dir / "in.csv").string();
  EXPECT_THROW(check({"--in", in, "-o", in}), FileError);
  EXPECT_NO_THROW(check({"--in", in, "-o", (dir / "new.csv").string()}));
  EXPECT_NO_THROW(check({"--robot", "ur5", "-o", "ur5"}));  // a name, not the file ./ur5
  EXPECT_THROW(check({"--robot", in, "-o", in}), FileError);
  EXPECT_THROW(check({"--reproduce", (dir / "rep").string(), "-o",
                      (dir / "rep" / "reproduce.json").string()}),
               FileError);
  EXPECT_THROW(check({"--in", in, "--out-dir", dir.string()}), FileError);
  EXPECT_NO_THROW(check({"--in", in, "--out-dir", (dir / "rep").string()}));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::cli
