// SPDX-License-Identifier: Apache-2.0
#include "command_registry.hpp"

namespace vrreg::cli {

std::vector<CommandEntry>& command_registry() {
  static std::vector<CommandEntry> registry;
  return registry;
}

}  // namespace vrreg::cli
