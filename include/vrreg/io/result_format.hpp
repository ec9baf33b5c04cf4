// SPDX-License-Identifier: Apache-2.0
#pragma once
// Results printable with fmt ({} gives the brief report, io/result_json.hpp) and with iostreams.
// Only a program that includes this header needs fmt.
#include <fmt/format.h>

#include <ostream>
#include <string_view>

#include "vrreg/io/result_json.hpp"

namespace vrreg {

inline std::ostream& operator<<(std::ostream& out, const RegisterResult& r) {
  return out << io::brief_report(r);
}
inline std::ostream& operator<<(std::ostream& out, const EvaluateResult& r) {
  return out << io::brief_report(r);
}
inline std::ostream& operator<<(std::ostream& out, const CorrectResult& r) {
  return out << io::brief_report(r);
}

}  // namespace vrreg

namespace vrreg::io::detail {
/// fmt::format("{}", result): the result's brief report.
template <typename Result>
struct BriefFormatter : fmt::formatter<std::string_view> {
  auto format(const Result& r, fmt::format_context& ctx) const {
    return fmt::formatter<std::string_view>::format(brief_report(r), ctx);
  }
};
}  // namespace vrreg::io::detail

template <>
struct fmt::formatter<vrreg::RegisterResult>
    : vrreg::io::detail::BriefFormatter<vrreg::RegisterResult> {};
template <>
struct fmt::formatter<vrreg::EvaluateResult>
    : vrreg::io::detail::BriefFormatter<vrreg::EvaluateResult> {};
template <>
struct fmt::formatter<vrreg::CorrectResult>
    : vrreg::io::detail::BriefFormatter<vrreg::CorrectResult> {};
