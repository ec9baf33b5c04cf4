// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to io: doubles as base64 of their little-endian IEEE 754 bytes, for the large arrays
// of a model file (a corrector's table): a quarter of the decimal text, read back to the bit and
// without parsing a number per value.
#include <optional>
#include <string>
#include <vector>

namespace vrreg::io::detail {

/// Base64 (RFC 4648, with padding) of the 8 little-endian bytes of each value, in order.
std::string doubles_to_base64(const double* values, std::size_t count);

/// The values doubles_to_base64 wrote, or nullopt when `text` is not such a string.
std::optional<std::vector<double>> base64_to_doubles(const std::string& text);

}  // namespace vrreg::io::detail
