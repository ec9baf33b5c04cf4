// SPDX-License-Identifier: Apache-2.0
#pragma once
// A command never writes over its own input: measurements cost hours of robot time.
#include <string>
#include <vector>

namespace vrreg::io {

/// A file a command reads or writes and the option that named it ("--fiducials", "-o").
struct CommandPath {
  std::string option{};
  std::string path{};  ///< empty: the option was not given
};

/// Throws FileError naming the output when an output is the same file as an input or as another
/// output: same device and inode (hard links, symbolic links), or the same path once `..` and
/// links are resolved, and (check_output_replaceable) when an output names a directory, FIFO,
/// device, socket or read-only file. Empty paths are skipped. Call it before any other work.
void check_outputs_are_not_inputs(const std::vector<CommandPath>& inputs,
                                  const std::vector<CommandPath>& outputs);

}  // namespace vrreg::io
