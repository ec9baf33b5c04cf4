// SPDX-License-Identifier: Apache-2.0
#pragma once
// Runs a check as an unprivileged user, for the permission cases root would bypass.
#include <grp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>

namespace vrreg::testing {

constexpr uid_t kNobody = 65534;

/// True when this process is root and can hand work to `nobody`.
inline bool is_root() { return ::geteuid() == 0; }

/// Runs `check` in a child process as `nobody` (uid and gid 65534, no supplementary groups);
/// true when it returned true. Only for root: the caller skips otherwise.
inline bool run_as_nobody(const std::function<bool()>& check) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::setgroups(0, nullptr) != 0 || ::setgid(kNobody) != 0 || ::setuid(kNobody) != 0) {
      ::_exit(3);
    }
    bool ok = false;
    try {
      ok = check();
    } catch (...) {
      ok = false;
    }
    ::_exit(ok ? 0 : 1);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace vrreg::testing
