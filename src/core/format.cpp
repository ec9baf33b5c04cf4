// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/format.hpp"

#include <fmt/format.h>

#include "vrreg/core/units.hpp"

namespace vrreg {

std::string format_fixed(double value, int decimals) {
  return fmt::format("{:.{}f}", value, decimals);
}

std::string format_general(double value, int significant) {
  return fmt::format("{:.{}g}", value, significant);
}

std::string format_mm(double length_m, int decimals) {
  return format_fixed(units::m_to_mm(length_m), decimals);
}

std::string format_mm3(const Eigen::Vector3d& v_m, int decimals) {
  return fmt::format("[{}, {}, {}]", format_mm(v_m.x(), decimals), format_mm(v_m.y(), decimals),
                     format_mm(v_m.z(), decimals));
}

std::string with_option_words(std::string message, std::span<const OptionWord> words) {
  for (const auto& [name, word] : words) {
    const std::string quoted = "`" + std::string(name) + "`";
    for (std::size_t at = 0; (at = message.find(quoted, at)) != std::string::npos;) {
      message.replace(at, quoted.size(), word);
      at += word.size();
    }
  }
  return message;
}

}  // namespace vrreg
