// SPDX-License-Identifier: Apache-2.0
#pragma once
// Input files are regular files: a FIFO with no writer would block the reader forever, a device
// never ends, a directory is not a file. Every reader opens its file through here.
#include <fstream>
#include <string>

namespace vrreg::io {

/// Opens `path` for binary reading; throws FileError "path: ... not a regular file" for a FIFO,
/// device, socket or directory (checked before opening, so nothing blocks), or "path: cannot
/// open: reason".
std::ifstream open_input_file(const std::string& path);

/// The whole content of `path`, opened as open_input_file() does.
std::string read_input_file(const std::string& path);

}  // namespace vrreg::io
