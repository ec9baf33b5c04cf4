// SPDX-License-Identifier: Apache-2.0
#include "escape.hpp"

#include <cctype>

namespace vrreg::report {

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string json_for_script(const nlohmann::json& value) {
  const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else if (c == '\xE2' && i + 2 < text.size() && text[i + 1] == '\x80' &&
               (text[i + 2] == '\xA8' || text[i + 2] == '\xA9')) {
      out += text[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";  // line / paragraph separator
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

namespace {

bool starts_with_nocase(std::string_view text, std::size_t at, std::string_view prefix) {
  if (text.size() - at < prefix.size()) return false;
  for (std::size_t k = 0; k < prefix.size(); ++k) {
    const auto a = static_cast<unsigned char>(text[at + k]);
    if (std::tolower(a) != prefix[k]) return false;
  }
  return true;
}

}  // namespace

std::string js_for_script(std::string_view source) {
  std::string out;
  out.reserve(source.size());
  for (std::size_t i = 0; i < source.size(); ++i) {
    if (source[i] == '<' && starts_with_nocase(source, i, "</script")) {
      out += "<\\/";
      ++i;  // skip the '/', the loop adds the rest
    } else if (source[i] == '<' && starts_with_nocase(source, i, "<!--")) {
      out += "\\x3C";
    } else {
      out += source[i];
    }
  }
  return out;
}

}  // namespace vrreg::report
