// SPDX-License-Identifier: Apache-2.0
#include "text_checks.hpp"

#include <cstdio>

namespace vrreg::io::detail {
namespace {

// Length of the valid UTF-8 sequence starting at s[i], or 0 when it is invalid (overlong forms,
// surrogates and code points above U+10FFFF are invalid).
std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  std::size_t n = 0;
  unsigned char lo = 0x80;
  unsigned char hi = 0xBF;
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) lo = 0xA0;
    if (b0 == 0xED) hi = 0x9F;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) lo = 0x90;
    if (b0 == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return n;
}

std::string hex_byte(unsigned char b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", static_cast<unsigned>(b));
  return buf;
}

}  // namespace

std::optional<std::string> find_non_text(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size()) {
    const auto b = static_cast<unsigned char>(line[i]);
    if (b == 0) {
      return "NUL byte at column " + std::to_string(i + 1) + " (binary data, not a text file)";
    }
    if (b < 0x20 && b != '\t') {
      return "control byte " + hex_byte(b) + " at column " + std::to_string(i + 1) +
             " (binary data, not a text file)";
    }
    if (b == 0x7F) {
      return "control byte 0x7F at column " + std::to_string(i + 1) + " (not a text file)";
    }
    if (b < 0x80) {
      ++i;
      continue;
    }
    const std::size_t n = utf8_sequence_length(line, i);
    if (n == 0) {
      return "invalid UTF-8 byte " + hex_byte(b) + " at column " + std::to_string(i + 1) +
             " (binary data or a non-UTF-8 encoding)";
    }
    i += n;
  }
  return std::nullopt;
}

std::string printable(std::string_view text, std::size_t max_chars) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto b = static_cast<unsigned char>(text[i]);
    const bool continuation = (b & 0xC0) == 0x80;
    if (out.size() >= max_chars && !continuation) {
      out += "...";
      break;
    }
    if (b >= 0x20 && b != 0x7F) {
      out += static_cast<char>(b);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(b));
      out += buf;
    }
  }
  return out;
}

}  // namespace vrreg::io::detail
