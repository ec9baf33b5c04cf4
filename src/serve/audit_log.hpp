// SPDX-License-Identifier: Apache-2.0
#pragma once
// The audit log: one JSON line per correction (time, client, protocol, model name and SHA-256,
// input, output, predicted sd, status), so that a part's corrected position can be traced to the
// model file and request it came from. Rotated by size: FILE, FILE.1, ... FILE.<keep>.
#include <cstddef>
#include <mutex>
#include <string>

#include "request.hpp"

namespace vrreg::serve {

struct AuditLogOptions {
  std::string path;                       ///< empty: no audit log
  std::size_t max_bytes = 64u << 20;      ///< rotate when the file reaches this size
  int keep = 5;                           ///< rotated files kept (FILE.1 newest)
};

class AuditLog {
 public:
  /// Opens (appends to) options.path; throws FileError when it cannot be opened or is not a
  /// regular file (a FIFO, a device).
  explicit AuditLog(AuditLogOptions options);
  ~AuditLog();
  AuditLog(const AuditLog&) = delete;
  AuditLog& operator=(const AuditLog&) = delete;

  [[nodiscard]] bool enabled() const { return fd_ >= 0; }

  /// Appends one line (buffered; written at once when 64 KiB are waiting, else by flush()).
  void record(const std::string& client, const char* protocol, const std::string& model_name,
              const std::string& model_sha256, const PointRequest& request,
              const PointAnswer& answer);
  /// Appends one line for a request refused before it named a point (malformed, unauthorized,
  /// over a bound): who sent it and why it was refused.
  void record_refusal(const std::string& client, const char* protocol, ReplyCode code,
                      const std::string& reason);
  /// Writes what is buffered and rotates when the file is full. Called every 100 ms by the service.
  void flush();
  /// The last write error, empty when none.
  [[nodiscard]] std::string error() const;

 private:
  void write_locked();
  void rotate_locked();

  AuditLogOptions options_;
  mutable std::mutex mutex_;
  std::string buffer_;
  std::size_t file_bytes_ = 0;
  int fd_ = -1;
  std::string error_;
};

}  // namespace vrreg::serve
