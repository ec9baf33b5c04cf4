// SPDX-License-Identifier: Apache-2.0
#include "token.hpp"

#include <cstdlib>

#include "vrreg/core/file_error.hpp"
#include "vrreg/io/input_file.hpp"

namespace vrreg::serve {

std::string read_token(const std::string& path) {
  if (path.empty()) {
    const char* env = std::getenv("VRREG_SERVE_TOKEN");
    return env ? env : "";
  }
  std::string text = io::read_input_file(path);
  const std::size_t end = text.find_first_of("\r\n");
  if (end != std::string::npos) text.resize(end);
  if (text.empty()) throw FileError(path, 1, "--token-file: the first line holds no token");
  return text;
}

}  // namespace vrreg::serve
