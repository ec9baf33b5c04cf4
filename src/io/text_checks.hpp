// SPDX-License-Identifier: Apache-2.0
#pragma once
// Checks that a line read from a file is text: no NUL or control bytes, valid UTF-8.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace vrreg::io::detail {

/// Describes the first byte that makes `line` not text (NUL, control byte, invalid UTF-8), if any.
std::optional<std::string> find_non_text(std::string_view line);

/// `text` for a message: control bytes escaped as \xNN, cut after about `max_chars` bytes.
std::string printable(std::string_view text, std::size_t max_chars = 60);

}  // namespace vrreg::io::detail
