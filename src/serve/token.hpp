// SPDX-License-Identifier: Apache-2.0
#pragma once
// The service's shared token: from a file (its first line, kept out of the process list and the
// shell history) or, without one, from $VRREG_SERVE_TOKEN.
#include <string>

namespace vrreg::serve {

/// The first line of `path`, or $VRREG_SERVE_TOKEN (possibly empty) when `path` is empty. Throws
/// FileError when the file cannot be read or its first line is empty.
std::string read_token(const std::string& path);

}  // namespace vrreg::serve
