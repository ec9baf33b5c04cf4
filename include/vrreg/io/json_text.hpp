// SPDX-License-Identifier: Apache-2.0
#pragma once
// JSON documents read from files, within stated limits (docs/file-formats.md): a hostile or broken
// file ends in a one-line FileError naming it, never a crash or a runaway.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace vrreg::io {

/// Deepest nesting of lists and objects a JSON or YAML document may have (vrreg's files need 4).
inline constexpr std::size_t kMaxDocumentDepth = 64;
/// Most values a YAML document may expand to (its aliases included).
inline constexpr std::size_t kMaxDocumentValues = 100'000;

/// Parses JSON `text` read from `source`. Syntax errors, nesting deeper than kMaxDocumentDepth,
/// numbers beyond the range of a double and invalid UTF-8 throw FileError with the line where
/// known. `what` names the expected file in the messages ("model file", "robot file").
nlohmann::json parse_json_document(const std::string& text, const std::string& source,
                                   const std::string& what);

/// A value from a file for an error message: compact JSON, at most 60 characters (then "..."),
/// a long list or object by its size, invalid UTF-8 replaced: a message never echoes unbounded
/// input.
std::string quote_value(const nlohmann::json& value);

/// 1-based line of the byte at 1-based offset `byte` of `text`.
std::size_t line_of_byte(const std::string& text, std::size_t byte);

}  // namespace vrreg::io
