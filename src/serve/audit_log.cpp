// SPDX-License-Identifier: Apache-2.0
#include "audit_log.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>

#include "line_protocol.hpp"
#include "served_model.hpp"
#include "vrreg/core/file_error.hpp"

namespace vrreg::serve {
namespace {

// Written at once when this much waits, so that a file overshoots its rotation size by at most
// an eighth of it.
std::size_t flush_bytes(std::size_t max_bytes) { return std::min<std::size_t>(64u << 10, max_bytes / 8); }

// Non-blocking: opening a FIFO for writing would otherwise wait for a reader (for ever, at start).
int open_append(const std::string& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NONBLOCK, 0640);
}

std::string mm3_text(const Eigen::Vector3d& v) {
  return "[" + format_reply_number(v.x()) + "," + format_reply_number(v.y()) + "," +
         format_reply_number(v.z()) + "]";
}

std::string quaternion_text(const Eigen::Quaterniond& q) {
  const Eigen::VectorXd xyzw = orientation_in(q, OrientationForm::kQuaternion);
  return "[" + format_reply_number(xyzw(0)) + "," + format_reply_number(xyzw(1)) + "," +
         format_reply_number(xyzw(2)) + "," + format_reply_number(xyzw(3)) + "]";
}

}  // namespace

AuditLog::AuditLog(AuditLogOptions options) : options_(std::move(options)) {
  if (options_.path.empty()) return;
  if (options_.keep < 1) throw InputError("audit log: keep at least 1 rotated file");
  if (options_.max_bytes < 4096) throw InputError("audit log: rotate at 4096 bytes or more");
  fd_ = open_append(options_.path);
  if (fd_ < 0 && errno == ENXIO) {  // a FIFO nobody reads
    throw FileError(options_.path, 0, "not a regular file (a FIFO): the audit log must be a file");
  }
  if (fd_ < 0) throw FileError(options_.path, 0, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  // Only a regular file can be rotated and keeps what is written (/dev/full takes nothing, a
  // FIFO blocks when full): anything else is refused at start, not discovered in production.
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    throw FileError(options_.path, 0, "not a regular file: the audit log must be a file");
  }
  file_bytes_ = static_cast<std::size_t>(st.st_size);
}

AuditLog::~AuditLog() {
  flush();
  if (fd_ >= 0) ::close(fd_);
}

void AuditLog::record(const std::string& client, const char* protocol,
                      const std::string& model_name, const std::string& model_sha256,
                      const PointRequest& request, const PointAnswer& answer) {
  if (fd_ < 0) return;
  std::string line = fmt::format(R"({{"time":"{}","client":"{}","protocol":"{}","model":)",
                                 utc_now(), client, protocol);
  line += nlohmann::json(model_name).dump();
  line += R"(,"sha256":")" + model_sha256 + R"(","sensor_mm":)" + mm3_text(request.sensor_mm);
  if (request.config) line += fmt::format(R"(,"config":{})", *request.config);
  if (!request.joints_rad.empty()) line += ",\"joints_rad\":" + nlohmann::json(request.joints_rad).dump();
  if (!request.from_rad.empty()) line += ",\"from_rad\":" + nlohmann::json(request.from_rad).dump();
  if (!request.approach_sign.empty()) {
    std::vector<int> signs(request.approach_sign.begin(), request.approach_sign.end());
    line += ",\"approach\":" + nlohmann::json(signs).dump();
  }
  if (request.extrapolate) line += R"(,"extrapolate":true)";
  if (request.q_sensor_marker)
    line += R"(,"sensor_q":)" + quaternion_text(*request.q_sensor_marker);
  line += R"(,"status":)" + nlohmann::json(answer.status).dump();
  if (answer.code == ReplyCode::kOk) {
    line += R"(,"robot_mm":)" + mm3_text(answer.robot_mm) + R"(,"predicted_sd_mm":)" +
            format_reply_number(answer.sd_mm);
    if (answer.q_robot_marker) {
      line += R"(,"robot_q":)" + quaternion_text(*answer.q_robot_marker) +
              R"(,"predicted_angle_sd_mrad":)" + format_reply_number(1e3 * answer.angle_sd_rad);
    }
  } else {
    line += fmt::format(R"(,"code":{},"reason":)", static_cast<int>(answer.code)) +
            nlohmann::json(answer.reason).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }
  line += "}\n";
  const std::lock_guard lock(mutex_);
  buffer_ += line;
  if (buffer_.size() >= flush_bytes(options_.max_bytes)) write_locked();
}

void AuditLog::record_refusal(const std::string& client, const char* protocol, ReplyCode code,
                              const std::string& reason) {
  if (fd_ < 0) return;
  std::string line = fmt::format(R"({{"time":"{}","client":"{}","protocol":"{}","status":)",
                                 utc_now(), client, protocol);
  line += nlohmann::json(to_string(code)).dump();
  line += fmt::format(R"(,"code":{},"reason":)", static_cast<int>(code)) +
          nlohmann::json(reason).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) +
          "}\n";
  const std::lock_guard lock(mutex_);
  buffer_ += line;
  if (buffer_.size() >= flush_bytes(options_.max_bytes)) write_locked();
}

void AuditLog::flush() {
  const std::lock_guard lock(mutex_);
  write_locked();
}

std::string AuditLog::error() const {
  const std::lock_guard lock(mutex_);
  return error_;
}

void AuditLog::write_locked() {
  if (fd_ < 0 || buffer_.empty()) return;
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error_ = options_.path + ": " + std::strerror(errno);
      std::fprintf(stderr, "vrreg serve: audit log %s\n", error_.c_str());
      break;  // kept in the buffer: written when the disk has room again
    }
    done += static_cast<std::size_t>(n);
  }
  buffer_.erase(0, done);
  file_bytes_ += done;
  if (buffer_.empty()) error_.clear();
  if (file_bytes_ >= options_.max_bytes) rotate_locked();
}

void AuditLog::rotate_locked() {
  ::close(fd_);
  const auto name = [&](int k) { return k == 0 ? options_.path : options_.path + "." + std::to_string(k); };
  std::remove(name(options_.keep).c_str());
  for (int k = options_.keep - 1; k >= 0; --k) std::rename(name(k).c_str(), name(k + 1).c_str());
  fd_ = open_append(options_.path);
  file_bytes_ = 0;
  if (fd_ < 0) {
    error_ = options_.path + ": cannot reopen after rotation: " + std::strerror(errno);
    std::fprintf(stderr, "vrreg serve: audit log %s\n", error_.c_str());
  }
}

}  // namespace vrreg::serve
