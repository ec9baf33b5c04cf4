// SPDX-License-Identifier: Apache-2.0
#pragma once
// The temporary files being written right now, so that a signal handler can remove them: a fixed
// table in static storage, read by the handler with atomics only (async-signal-safe).
#include <string>

namespace vrreg::io::detail {

/// Remembers `path` until forget_temporary(); returns its slot, or -1 when the table is full or
/// the path too long (that file is then not removed on a signal). Remember a name before creating
/// the file: a signal may reach another thread, which cannot be held off, at any moment.
int remember_temporary(const std::string& path);

/// Forgets the slot of remember_temporary() (-1 is ignored).
void forget_temporary(int slot);

}  // namespace vrreg::io::detail
