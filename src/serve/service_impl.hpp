// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to the service: what its sessions share. Includes Boost.Asio: only the service's own
// sources include this.
#include <utility>  // before Boost.Asio 1.74's awaitable.hpp, which uses std::exchange unincluded

#include <boost/asio.hpp>
#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <string_view>
#include <thread>
#include <vector>

#include "service.hpp"

namespace vrreg::serve {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

struct Service::Impl {
  Impl(ServeOptions options, Log log);

  // Declared so that io is destroyed after everything its pending sessions touch (options,
  // registry, audit, counters) and before the acceptors it owns' services back.
  ServeOptions options;
  Log log;
  ModelRegistry registry;
  AuditLog audit;
  std::atomic<unsigned long long> corrections{0};
  std::atomic<unsigned long long> refusals{0};
  std::atomic<unsigned long long> connections{0};
  std::atomic<unsigned long long> rejected{0};
  std::atomic<unsigned long long> malformed{0};
  std::atomic<unsigned long long> unauthorized{0};
  std::atomic<unsigned long long> limited{0};
  std::atomic<int> open_line{0};
  std::atomic<int> open_http{0};
  std::atomic<bool> stopping{false};
  std::atomic<bool> reloading{false};
  asio::io_context io;
  std::optional<asio::executor_work_guard<asio::io_context::executor_type>> work;
  std::optional<tcp::acceptor> line_acceptor;
  std::optional<tcp::acceptor> http_acceptor;
  asio::thread_pool reloader{1};  ///< loads models off the threads that answer
  std::vector<std::thread> threads;
  // Declared after io: destroyed first, so that a batch still queued there, which holds its
  // session, lets the session go while io and its sockets are still there.
  asio::io_context batch_io;  ///< answers batches, off the threads robots wait on
  std::optional<asio::executor_work_guard<asio::io_context::executor_type>> batch_work;
  std::vector<std::thread> batch_threads;

  /// Answers one point with `model` (null: not served): corrects, counts and audits.
  PointAnswer answer(const std::shared_ptr<const ServedModel>& model, const PointRequest& request,
                     const std::string& client, const char* protocol);
  /// Whether `given` is the token (always true when the service has none).
  [[nodiscard]] bool authorized(const std::string& given) const;
  /// Counts a request refused before it named a point (malformed, unauthorized, over a bound)
  /// and says so in the service log and the audit log, at most kRefusalLogBurst lines per
  /// kRefusalLogWindow (a port scan or a fuzzing client must not flood either).
  void refused_request(const std::string& client, const char* protocol, ReplyCode code,
                       const std::string& reason);
  [[nodiscard]] ServiceStats stats() const;

  void log_line(const std::string& message) const;

  static constexpr int kRefusalLogBurst = 20;
  static constexpr std::chrono::seconds kRefusalLogWindow{10};

 private:
  std::mutex refusal_log_mutex_;
  std::chrono::steady_clock::time_point refusal_window_start_{};
  int refusals_logged_ = 0;
  unsigned long long refusals_unlogged_ = 0;
};

/// `s` seconds as a steady-clock duration (timeouts are options in seconds).
inline std::chrono::steady_clock::duration after_seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(s));
}

/// Counts an open connection for its lifetime.
class OpenConnection {
 public:
  explicit OpenConnection(std::atomic<int>& open) : open_(open) { ++open_; }
  ~OpenConnection() { --open_; }
  OpenConnection(const OpenConnection&) = delete;
  OpenConnection& operator=(const OpenConnection&) = delete;

 private:
  std::atomic<int>& open_;
};

/// "address:port" of the peer, or "?" when the socket has none any more.
std::string peer_of(const tcp::socket& socket);

/// What a line-protocol connection carries from one request to the next.
struct LineState {
  bool authorized = false;
};

/// The reply to one line-protocol request and whether the connection closes after it.
struct LineOutcome {
  std::string reply;
  bool close = false;
};

/// Answers one request line (`line` without its '\n'; a trailing '\r' is dropped): reads it,
/// checks the token and the length bound, corrects, counts, logs and audits. Never throws.
LineOutcome handle_line(Service::Impl& service, std::string_view line, LineState& state,
                        const std::string& client);

asio::awaitable<void> line_session(Service::Impl& service, tcp::socket socket);
asio::awaitable<void> http_session(Service::Impl& service, tcp::socket socket);

}  // namespace vrreg::serve
