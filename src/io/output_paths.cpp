// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/output_paths.hpp"

#include <sys/stat.h>

#include <filesystem>

#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io {
namespace {

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {};
  struct stat sb {};
  if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0) {
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  }
  // One of them does not exist yet (two outputs): compare the resolved names.
  std::error_code ea;
  std::error_code eb;
  const auto ca = std::filesystem::weakly_canonical(a, ea);
  const auto cb = std::filesystem::weakly_canonical(b, eb);
  return !ea && !eb && ca == cb;
}

}  // namespace

void check_outputs_are_not_inputs(const std::vector<CommandPath>& inputs,
                                  const std::vector<CommandPath>& outputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const CommandPath& out = outputs[k];
    if (out.path.empty()) continue;
    check_output_replaceable(out.path);  // a directory, FIFO or device: refused before any work
    for (const CommandPath& in : inputs) {
      if (in.path.empty() || !same_file(out.path, in.path)) continue;
      throw FileError(out.path, 0,
                      out.option + " is the input " + in.option + " '" + in.path +
                          "': refusing to overwrite it (nothing was written)");
    }
    for (std::size_t j = 0; j < k; ++j) {
      const CommandPath& other = outputs[j];
      if (other.path.empty() || !same_file(out.path, other.path)) continue;
      throw FileError(out.path, 0,
                      out.option + " is the same file as " + other.option + " '" + other.path +
                          "': give each output its own name (nothing was written)");
    }
  }
}

}  // namespace vrreg::io
