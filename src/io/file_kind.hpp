// SPDX-License-Identifier: Apache-2.0
#pragma once
// Words for what a non-regular file is, shared by the input and output checks.
#include <sys/stat.h>

namespace vrreg::io::detail {

/// "is a directory", "is a FIFO", ... for a stat mode that is not a regular file.
inline const char* file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a FIFO";
  if (S_ISSOCK(mode)) return "is a socket";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device";
  return "is a special file";
}

}  // namespace vrreg::io::detail
