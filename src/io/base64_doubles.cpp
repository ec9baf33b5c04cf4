// SPDX-License-Identifier: Apache-2.0
#include "base64_doubles.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

namespace vrreg::io::detail {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

}  // namespace

std::string doubles_to_base64(const double* values, std::size_t count) {
  std::vector<unsigned char> bytes(count * 8);
  for (std::size_t i = 0; i < count; ++i) {
    const auto bits = std::bit_cast<std::uint64_t>(values[i]);
    for (int b = 0; b < 8; ++b) bytes[i * 8 + static_cast<std::size_t>(b)] = static_cast<unsigned char>(bits >> (8 * b));
  }
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t{bytes[i]} << 16U) |
                            (i + 1 < bytes.size() ? std::uint32_t{bytes[i + 1]} << 8U : 0U) |
                            (i + 2 < bytes.size() ? std::uint32_t{bytes[i + 2]} : 0U);
    out += kAlphabet[(n >> 18U) & 63U];
    out += kAlphabet[(n >> 12U) & 63U];
    out += i + 1 < bytes.size() ? kAlphabet[(n >> 6U) & 63U] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[n & 63U] : '=';
  }
  return out;
}

std::optional<std::vector<double>> base64_to_doubles(const std::string& text) {
  if (text.size() % 4 != 0) return std::nullopt;
  std::vector<unsigned char> bytes;
  bytes.reserve(text.size() / 4 * 3);
  for (std::size_t i = 0; i < text.size(); i += 4) {
    std::array<int, 4> s{};
    int pad = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const char c = text[i + k];
      const bool last = i + 4 == text.size();
      if (c == '=' && last && k >= 2) {
        ++pad;
        s[k] = 0;
        continue;
      }
      if (pad > 0) return std::nullopt;  // data after padding
      s[k] = sextet(c);
      if (s[k] < 0) return std::nullopt;
    }
    const std::uint32_t n = (static_cast<std::uint32_t>(s[0]) << 18U) |
                            (static_cast<std::uint32_t>(s[1]) << 12U) |
                            (static_cast<std::uint32_t>(s[2]) << 6U) | static_cast<std::uint32_t>(s[3]);
    bytes.push_back(static_cast<unsigned char>(n >> 16U));
    if (pad < 2) bytes.push_back(static_cast<unsigned char>(n >> 8U));
    if (pad < 1) bytes.push_back(static_cast<unsigned char>(n));
  }
  if (bytes.size() % 8 != 0) return std::nullopt;
  std::vector<double> out(bytes.size() / 8);
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::uint64_t bits = 0;
    for (int b = 0; b < 8; ++b) bits |= std::uint64_t{bytes[i * 8 + static_cast<std::size_t>(b)]} << (8 * b);
    out[i] = std::bit_cast<double>(bits);
  }
  return out;
}

}  // namespace vrreg::io::detail
