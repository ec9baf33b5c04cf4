// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the robot file reader (src/robot_io), as JSON, as YAML and sniffed.
#include "fuzz_support.hpp"
#include "vrreg/robot_io/robot_file.hpp"

namespace vrreg::fuzz {

int robot_file(const std::uint8_t* data, std::size_t size) {
  const std::string text = as_text(data, size);
  const struct {
    io::RobotFileSyntax syntax;
    const char* source;
  } cases[] = {{io::RobotFileSyntax::kJson, "fuzz.json"},
               {io::RobotFileSyntax::kYaml, "fuzz.yaml"},
               {io::RobotFileSyntax::kAuto, "fuzz"}};
  for (const auto& c : cases) {
    reads_or_refuses("robot file", [&] { (void)io::parse_robot_file(text, c.source, c.syntax); });
  }
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::robot_file)
