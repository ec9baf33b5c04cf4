// SPDX-License-Identifier: Apache-2.0
#pragma once
// Errors in input files: the message names the file and, where there is one, the line. In core so
// that every module that knows where its input came from can name it (design.md 7).
#include <cstddef>
#include <string>

#include "vrreg/core/check.hpp"

namespace vrreg {

/// Bad content in a file: what() reads "path:line: message" (or "path: message" when line is 0),
/// always one line (control characters in path or message are written as escapes: \n, \x01).
class FileError : public InputError {
 public:
  FileError(const std::string& path, std::size_t line, const std::string& message);
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::size_t line() const { return line_; }

 private:
  std::string path_{};
  std::size_t line_{};
};

}  // namespace vrreg
