// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal: a robot file parsed into JSON values, with the source line of each value where the
// syntax records one (YAML), so that errors can name "file:line: dh[2].d_m: ...".
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace vrreg::io::detail {

struct RobotDocument {
  nlohmann::json root;
  std::map<std::string, std::size_t> lines;  ///< key path ("dh[2].d_m") -> 1-based line

  /// Line of `path` or of its nearest recorded ancestor; 0 when unknown.
  [[nodiscard]] std::size_t line_of(std::string path) const;
  /// Throws FileError "source:line: path: message", the line that of `path`.
  [[noreturn]] void fail(const std::string& source, const std::string& path,
                         const std::string& message) const;
};

/// Parses JSON text (syntax errors throw FileError with the line).
RobotDocument parse_robot_json(const std::string& text, const std::string& source);
/// Parses YAML text into the same JSON model (numbers, strings, lists, maps, null).
RobotDocument parse_robot_yaml(const std::string& text, const std::string& source);

}  // namespace vrreg::io::detail
