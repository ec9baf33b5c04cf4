// SPDX-License-Identifier: Apache-2.0
#pragma once
// `vrreg serve`: a long-running process that loads fitted models once and answers correction
// requests concurrently, on a line protocol robot controllers speak and on HTTP/JSON
// (docs/serve.md). Boost.Asio's thread pool and Boost.Beast's HTTP underneath.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "audit_log.hpp"
#include "model_registry.hpp"

namespace vrreg::serve {

/// Where to listen: an IPv4 or IPv6 address and a port (0: any free port).
struct Endpoint {
  std::string address = "127.0.0.1";
  unsigned short port = 0;
};

/// "ADDRESS:PORT", "[IPv6]:PORT" or "PORT" (on 127.0.0.1); "localhost" is 127.0.0.1. Throws
/// InputError.
Endpoint parse_endpoint(const std::string& text);

struct ServeOptions {
  std::vector<ModelSource> models;   ///< the first is the one the health check names first
  std::optional<Endpoint> line;      ///< the line protocol (--listen)
  std::optional<Endpoint> http;      ///< HTTP/JSON (--http)
  /// Addresses other than loopback are refused unless allowed, and then need a token.
  bool allow_remote = false;
  std::string token;                 ///< shared secret; empty: none (loopback only)
  int threads = 0;                   ///< 0: the machine's cores
  std::size_t max_line_bytes = 1024;
  std::size_t max_body_bytes = 1u << 20;
  std::size_t max_batch = 10000;
  /// Open connections at most, each protocol its own budget: HTTP clients (which may hold a
  /// connection idle for the idle timeout) never take a robot's line-protocol slot.
  int max_connections = 256;       ///< line protocol (--max-connections)
  int max_http_connections = 256;  ///< HTTP (--max-http-connections)
  /// Threads that answer HTTP batches (and bodies over 2 KiB), apart from the threads that read
  /// and answer the line protocol, so that a batch never delays a robot; 0: half the cores.
  int batch_threads = 0;
  /// An extrapolated answer farther from the fiducials' bounding box than this many times its
  /// diagonal is refused (code 8); infinity: no cap.
  double max_extrapolation = 1.0;
  double idle_timeout_s = 600.0;     ///< a connection silent this long is closed
  double io_timeout_s = 10.0;        ///< a request or reply not through in this time: closed
  int reload_poll_ms = 1000;         ///< check the model files this often; 0: SIGHUP only
  AuditLogOptions audit;

  /// Throws InputError naming the option when the options cannot be served.
  void validate() const;
};

/// Counters since the start (the health endpoint, the tests).
struct ServiceStats {
  unsigned long long corrections = 0;  ///< points answered (ok or refused)
  unsigned long long refusals = 0;
  unsigned long long connections = 0;  ///< accepted
  unsigned long long rejected_connections = 0;  ///< over max_connections
  int open_connections = 0;
  /// Requests refused before they named a point (also in `refusals`).
  unsigned long long malformed = 0;     ///< unreadable (code 1, HTTP 400)
  unsigned long long unauthorized = 0;  ///< no or a wrong token (code 5, HTTP 401)
  unsigned long long limited = 0;       ///< over a bound (code 6, HTTP 413)
  int open_line_connections = 0;
  int open_http_connections = 0;
};

class Service {
 public:
  using Log = std::function<void(const std::string&)>;
  /// Loads the models and binds the sockets; throws (FileError, InputError, or a system error
  /// naming the address) when either fails: a service starts whole or not at all.
  Service(ServeOptions options, Log log);
  ~Service();
  Service(const Service&) = delete;
  Service& operator=(const Service&) = delete;

  /// The ports bound (useful with port 0); 0 when that protocol is off.
  [[nodiscard]] unsigned short line_port() const;
  [[nodiscard]] unsigned short http_port() const;

  /// Starts the threads and returns.
  void start();
  /// Starts, then blocks until SIGINT or SIGTERM (SIGHUP reloads every model).
  void run_until_signalled();
  /// Stops accepting, closes the connections and joins the threads.
  void stop();
  /// Reloads changed model files now (all when `force`); returns how many were swapped in.
  int reload(bool force);

  [[nodiscard]] ServiceStats stats() const;
  [[nodiscard]] const ModelRegistry& models() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

/// Whether `a` and `b` are equal, in time that does not depend on where they differ (tokens).
bool constant_time_equal(const std::string& a, const std::string& b);

}  // namespace vrreg::serve
