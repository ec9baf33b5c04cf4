#pragma once
// Output files are written whole or not at all (design.md 6).
#include <string>

namespace vrreg::io {

/// Writes `content` to a temporary file beside `path`, flushes it to disk and renames it over
/// `path`; on any failure removes the temporary file and throws FileError naming `path`.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace vrreg::io
