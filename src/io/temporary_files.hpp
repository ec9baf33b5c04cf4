#pragma once
// The temporary files being written right now, so that a signal handler can remove them: a fixed
// table in static storage, read by the handler with atomics only (async-signal-safe).
#include <signal.h>

#include <string>

namespace vrreg::io::detail {

/// Remembers `path` until forget_temporary(); returns its slot, or -1 when the table is full or
/// the path too long (that file is then not removed on a signal).
int remember_temporary(const std::string& path);

/// Forgets the slot of remember_temporary() (-1 is ignored).
void forget_temporary(int slot);

/// Blocks SIGINT and SIGTERM in this thread while alive, so that creating and remembering a
/// temporary file (or renaming and forgetting it) is one step for the handler.
class SignalsHeld {
 public:
  SignalsHeld();
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;
  ~SignalsHeld();

 private:
  sigset_t saved_{};
};

}  // namespace vrreg::io::detail
