// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/input_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "file_kind.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io {

std::ifstream open_input_file(const std::string& path) {
  // stat before open: opening a FIFO for reading waits for a writer.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw FileError(path, 0, std::string(detail::file_kind(st.st_mode)) + ", not a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  return in;
}

std::string read_input_file(const std::string& path) {
  std::ifstream in = open_input_file(path);
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) throw FileError(path, 0, "read error");
  return content.str();
}

}  // namespace vrreg::io
