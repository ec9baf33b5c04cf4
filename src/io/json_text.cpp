// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/json_text.hpp"

#include <algorithm>

#include "vrreg/core/file_error.hpp"

namespace vrreg::io {
namespace {

using nlohmann::json;

// nlohmann's message without its "[json.exception...] parse error at line L, column C: " prefix.
std::string library_detail(const std::string& what) {
  std::string detail = what;
  const std::size_t bracket = detail.find("] ");
  if (bracket != std::string::npos) detail.erase(0, bracket + 2);
  const std::size_t colon = detail.find(": ");
  if (detail.starts_with("parse error") && colon != std::string::npos) detail.erase(0, colon + 2);
  return detail;
}

// Nesting checked before parsing, outside strings, so that a deep document is refused with its
// line before any recursive step (parsing, destruction, printing) could exhaust the stack.
void check_nesting(const std::string& text, const std::string& source) {
  std::size_t depth = 0, line = 1;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxDocumentDepth) {
        throw FileError(source, line,
                        "nested deeper than " + std::to_string(kMaxDocumentDepth) + " levels");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace

std::size_t line_of_byte(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  return 1 + static_cast<std::size_t>(
                 std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
}

json parse_json_document(const std::string& text, const std::string& source,
                         const std::string& what) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw FileError(source, 0, "empty file (expected a " + what + " in JSON)");
  }
  check_nesting(text, source);
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    throw FileError(
        source, line_of_byte(text, e.byte),
        "invalid JSON (truncated or corrupted " + what + "): " + library_detail(e.what()));
  } catch (const json::exception& e) {  // a number beyond a double, invalid UTF-8, ...
    throw FileError(source, 0, "invalid JSON: " + library_detail(e.what()));
  }
}

std::string quote_value(const json& value) {
  constexpr std::size_t kMaxChars = 60;
  if (value.is_structured() && value.size() > 8) {
    return std::string(value.is_array() ? "a list" : "an object") + " of " +
           std::to_string(value.size()) + " values";
  }
  std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > kMaxChars) {
    std::size_t cut = kMaxChars - 3;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // UTF-8
    text = text.substr(0, cut) + "...";
  }
  return text;
}

}  // namespace vrreg::io
