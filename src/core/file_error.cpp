// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/file_error.hpp"

#include <string>

namespace vrreg {
namespace {

// Control characters (a newline in a file name, a raw byte quoted by a parser) are written as
// escapes, so that the message is always one line.
std::string one_line(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

std::string format_message(const std::string& path, std::size_t line, const std::string& message) {
  if (line == 0) return one_line(path) + ": " + one_line(message);
  return one_line(path) + ":" + std::to_string(line) + ": " + one_line(message);
}

}  // namespace

FileError::FileError(const std::string& path, std::size_t line, const std::string& message)
    : InputError(format_message(path, line, message)), path_(path), line_(line) {}

}  // namespace vrreg
