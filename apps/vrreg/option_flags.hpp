// SPDX-License-Identifier: Apache-2.0
#pragma once
// The library names an option in its messages as `name` (its Python keyword: the C++ option
// without its unit suffix); the command line says its own flag instead, from one table.
#include <string>

namespace vrreg::cli {

/// `message` with every `name` of the table replaced by its flag (`cube_edge` -> --cube-mm);
/// names not in the table are left as they are.
std::string with_flags(std::string message);

}  // namespace vrreg::cli
