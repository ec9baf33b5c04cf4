// SPDX-License-Identifier: Apache-2.0
#include "service.hpp"

#include <fmt/format.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <future>
#include <cstdio>

#include "service_impl.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg::serve {
namespace {

// "localhost" is the name every user types for loopback; no resolver is asked (it could answer
// with anything /etc/hosts says).
asio::ip::address address_of(const std::string& text, boost::system::error_code& ec) {
  std::string lower = text;
  for (char& c : lower) c = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
  if (lower == "localhost") return asio::ip::address_v4::loopback();
  return asio::ip::make_address(text, ec);
}

tcp::acceptor bind(asio::io_context& io, const Endpoint& endpoint, const char* option) {
  boost::system::error_code ec;
  const asio::ip::address address = address_of(endpoint.address, ec);
  VRREG_THROW_UNLESS(!ec, option << " " << endpoint.address << ": not an IP address");
  tcp::acceptor acceptor(io);
  const tcp::endpoint at(address, endpoint.port);
  acceptor.open(at.protocol(), ec);
  if (!ec) acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor.bind(at, ec);
  if (!ec) acceptor.listen(asio::socket_base::max_listen_connections, ec);
  VRREG_THROW_UNLESS(!ec, option << " " << endpoint.address << ":" << endpoint.port
                                 << ": cannot listen: " << ec.message());
  return acceptor;
}

using Session = asio::awaitable<void> (*)(Service::Impl&, tcp::socket);

// Accepts until the acceptor closes; each connection gets its own strand, so that its timeouts
// and its reads and writes never run at once. Each protocol has its own budget of connections.
asio::awaitable<void> accept_loop(Service::Impl& service, tcp::acceptor& acceptor, Session session,
                                  const char* protocol, std::atomic<int>& open, int max_open) {
  boost::system::error_code ec;
  for (;;) {
    tcp::socket socket = co_await acceptor.async_accept(
        asio::make_strand(service.io), asio::redirect_error(asio::use_awaitable, ec));
    if (ec == asio::error::operation_aborted || !acceptor.is_open()) break;
    if (ec) continue;  // e.g. EMFILE: the next accept may succeed
    ++service.connections;
    if (open.load() >= max_open) {
      ++service.rejected;
      const std::string client = peer_of(socket);
      // Said, not silently dropped: a line client reads a refusal, an HTTP client a 503.
      const std::string refusal =
          std::string(protocol) == "line"
              ? std::string("(0,0,0,-6)\n")
              : std::string("HTTP/1.1 503 Service Unavailable\r\nContent-Length: 0\r\n"
                            "Connection: close\r\n\r\n");
      socket.non_blocking(true, ec);
      socket.write_some(asio::buffer(refusal), ec);
      socket.close(ec);
      service.refused_request(client, protocol, ReplyCode::kLimit,
                              fmt::format("over {} open {} connections", max_open, protocol));
      continue;
    }
    auto executor = socket.get_executor();
    asio::co_spawn(executor, session(service, std::move(socket)), asio::detached);
  }
}

asio::awaitable<void> every(Service::Impl& service, double period_s,
                            std::function<void()> task) {
  asio::steady_timer timer(co_await asio::this_coro::executor);
  boost::system::error_code ec;
  while (!service.stopping) {
    timer.expires_after(after_seconds(period_s));
    co_await timer.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    if (ec || service.stopping) break;
    task();
  }
}

bool is_loopback(const std::string& address) {
  boost::system::error_code ec;
  const asio::ip::address a = address_of(address, ec);
  return !ec && a.is_loopback();
}

std::array<unsigned char, 32> digest_of(const std::string& text) {
  std::array<unsigned char, 32> d{};
  unsigned int n = 0;
  EVP_Digest(text.data(), text.size(), d.data(), &n, EVP_sha256(), nullptr);
  return d;
}

}  // namespace

bool constant_time_equal(const std::string& a, const std::string& b) {
  // Comparing digests takes the same time whatever the lengths and wherever the texts differ.
  const auto da = digest_of(a);
  const auto db = digest_of(b);
  return CRYPTO_memcmp(da.data(), db.data(), da.size()) == 0;
}

Endpoint parse_endpoint(const std::string& text) {
  Endpoint e;
  std::string port = text;
  if (!text.empty() && text.front() == '[') {
    const std::size_t close = text.find("]:");
    VRREG_THROW_UNLESS(close != std::string::npos, "'" << text << "': expected [IPv6]:PORT");
    e.address = text.substr(1, close - 1);
    port = text.substr(close + 2);
  } else if (const std::size_t colon = text.rfind(':'); colon != std::string::npos) {
    e.address = text.substr(0, colon);
    port = text.substr(colon + 1);
  }
  unsigned value = 0;
  const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), value);
  VRREG_THROW_UNLESS(!port.empty() && error == std::errc() && end == port.data() + port.size() &&
                         value <= 65535,
                     "'" << text << "': expected ADDRESS:PORT with a port from 0 to 65535");
  e.port = static_cast<unsigned short>(value);
  return e;
}

void ServeOptions::validate() const {
  VRREG_THROW_UNLESS(!models.empty(), "--model: no model to serve");
  VRREG_THROW_UNLESS(line || http, "--listen or --http: nowhere to answer");
  for (const auto* e : {&line, &http}) {
    if (!*e) continue;
    const char* option = e == &line ? "--listen" : "--http";
    if (!is_loopback((*e)->address)) {
      VRREG_THROW_UNLESS(allow_remote, option << " " << (*e)->address
                                              << ": not a loopback address; serving the cell "
                                                 "network needs --allow-remote and a token");
      VRREG_THROW_UNLESS(!token.empty(), option << " " << (*e)->address
                                                << ": a remote address needs a token "
                                                   "(--token-file or VRREG_SERVE_TOKEN)");
    }
  }
  VRREG_THROW_UNLESS(token.empty() || token.size() >= 16,
                     "token: at least 16 characters (it is all that guards the cell)");
  for (const char c : token) {
    VRREG_THROW_UNLESS(c > 0x20 && c < 0x7f, "token: printable ASCII without spaces");
  }
  VRREG_THROW_UNLESS(threads >= 0 && threads <= 256, "--threads: 0 (the cores) to 256");
  VRREG_THROW_UNLESS(max_line_bytes >= 64 && max_line_bytes <= (1u << 20),
                     "max line: 64 B to 1 MiB");
  VRREG_THROW_UNLESS(max_body_bytes >= 1024 && max_body_bytes <= (256u << 20),
                     "--max-body-bytes: 1 KiB to 256 MiB");
  VRREG_THROW_UNLESS(max_batch >= 1 && max_batch <= 1000000, "--max-batch: 1 to 10^6");
  VRREG_THROW_UNLESS(max_connections >= 1 && max_connections <= 100000,
                     "--max-connections: 1 to 100000");
  VRREG_THROW_UNLESS(max_http_connections >= 1 && max_http_connections <= 100000,
                     "--max-http-connections: 1 to 100000");
  VRREG_THROW_UNLESS(batch_threads >= 0 && batch_threads <= 256,
                     "--batch-threads: 0 (half the cores) to 256");
  VRREG_THROW_UNLESS(
      max_extrapolation > 0,
      "--max-extrapolation: above 0 (times the fiducials' box diagonal; inf: no cap)");
  VRREG_THROW_UNLESS(idle_timeout_s > 0 && idle_timeout_s <= 86400,
                     "--idle-timeout-s: above 0, at most a day");
  VRREG_THROW_UNLESS(io_timeout_s > 0 && io_timeout_s <= 3600, "io timeout: above 0, at most 1 h");
  VRREG_THROW_UNLESS(reload_poll_ms >= 0 && reload_poll_ms <= 3600000,
                     "--reload-poll-ms: 0 (SIGHUP only) to an hour");
}

Service::Impl::Impl(ServeOptions o, Log l)
    : options((o.validate(), std::move(o))),
      log(std::move(l)),
      registry(options.models, log),
      audit(options.audit) {}

void Service::Impl::log_line(const std::string& message) const {
  if (log) log(message);
}

bool Service::Impl::authorized(const std::string& given) const {
  return options.token.empty() || constant_time_equal(given, options.token);
}

PointAnswer Service::Impl::answer(const std::shared_ptr<const ServedModel>& model,
                                  const PointRequest& request, const std::string& client,
                                  const char* protocol) {
  ++corrections;
  PointAnswer a = model ? model->answer(request, options.max_extrapolation)
                        : PointAnswer::refusal(ReplyCode::kUnknownModel,
                                               "no model named '" + request.model + "' is served");
  if (a.code != ReplyCode::kOk) ++refusals;
  static const std::string kNone = "-";
  audit.record(client, protocol, request.model, model ? model->identity().sha256 : kNone, request, a);
  return a;
}

void Service::Impl::refused_request(const std::string& client, const char* protocol, ReplyCode code,
                                    const std::string& reason) {
  ++refusals;
  if (code == ReplyCode::kMalformed) ++malformed;
  if (code == ReplyCode::kUnauthorized) ++unauthorized;
  if (code == ReplyCode::kLimit) ++limited;
  std::string summary;
  bool quiet = false;
  {
    const std::lock_guard lock(refusal_log_mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (now - refusal_window_start_ >= kRefusalLogWindow) {
      if (refusals_unlogged_ > 0) {
        summary = fmt::format("{} more refused requests not logged (at most {} per {} s)",
                              refusals_unlogged_, kRefusalLogBurst, kRefusalLogWindow.count());
      }
      refusal_window_start_ = now;
      refusals_logged_ = 0;
      refusals_unlogged_ = 0;
    }
    quiet = refusals_logged_ >= kRefusalLogBurst;
    if (quiet) {
      ++refusals_unlogged_;
    } else {
      ++refusals_logged_;
    }
  }
  if (!summary.empty()) log_line(summary);
  if (quiet) return;
  // The reason may quote the client's bytes: one printable line in the log, whatever they were.
  std::string shown = reason.substr(0, 200);
  for (char& c : shown) c = (c >= 0x20 && c < 0x7f) ? c : '?';
  if (reason.size() > shown.size()) shown += "...";
  log_line(fmt::format("{} request from {} refused ({} {}): {}", protocol, client,
                       static_cast<int>(code), to_string(code), shown));
  audit.record_refusal(client, protocol, code, reason);
}

ServiceStats Service::Impl::stats() const {
  ServiceStats s;
  s.corrections = corrections.load();
  s.refusals = refusals.load();
  s.connections = connections.load();
  s.rejected_connections = rejected.load();
  s.open_line_connections = open_line.load();
  s.open_http_connections = open_http.load();
  s.open_connections = s.open_line_connections + s.open_http_connections;
  s.malformed = malformed.load();
  s.unauthorized = unauthorized.load();
  s.limited = limited.load();
  return s;
}

std::string peer_of(const tcp::socket& socket) {
  boost::system::error_code ec;
  const tcp::endpoint e = socket.remote_endpoint(ec);
  if (ec) return "?";
  const std::string address = e.address().to_string();
  return (e.address().is_v6() ? "[" + address + "]" : address) + ":" + std::to_string(e.port());
}

Service::Service(ServeOptions options, Log log)
    : impl_(std::make_unique<Impl>(std::move(options), std::move(log))) {
  Impl& s = *impl_;
  if (s.options.line) s.line_acceptor.emplace(bind(s.io, *s.options.line, "--listen"));
  if (s.options.http) s.http_acceptor.emplace(bind(s.io, *s.options.http, "--http"));
}

Service::~Service() { stop(); }

unsigned short Service::line_port() const {
  return impl_->line_acceptor ? impl_->line_acceptor->local_endpoint().port() : 0;
}

unsigned short Service::http_port() const {
  return impl_->http_acceptor ? impl_->http_acceptor->local_endpoint().port() : 0;
}

void Service::start() {
  Impl& s = *impl_;
  if (!s.threads.empty()) return;
  s.work.emplace(asio::make_work_guard(s.io));
  if (s.line_acceptor) {
    asio::co_spawn(s.io,
                   accept_loop(s, *s.line_acceptor, &line_session, "line", s.open_line,
                               s.options.max_connections),
                   asio::detached);
  }
  if (s.http_acceptor) {
    asio::co_spawn(s.io,
                   accept_loop(s, *s.http_acceptor, &http_session, "http", s.open_http,
                               s.options.max_http_connections),
                   asio::detached);
  }
  if (s.audit.enabled()) {
    asio::co_spawn(s.io, every(s, 0.1, [&s] { s.audit.flush(); }), asio::detached);
  }
  if (s.options.reload_poll_ms > 0) {
    asio::co_spawn(s.io, every(s, s.options.reload_poll_ms / 1000.0, [this] {
                     Impl& i = *impl_;
                     if (i.reloading.exchange(true)) return;  // the last check is still loading
                     asio::post(i.reloader, [this] {
                       impl_->registry.reload(false);
                       impl_->reloading = false;
                     });
                   }),
                   asio::detached);
  }
  const int n = s.options.threads > 0
                    ? s.options.threads
                    : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  for (int i = 0; i < n; ++i) s.threads.emplace_back([&s] { s.io.run(); });
  s.batch_work.emplace(asio::make_work_guard(s.batch_io));
  const int n_batch = s.options.batch_threads > 0
                          ? s.options.batch_threads
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / 2);
  for (int i = 0; i < n_batch; ++i) {
    s.batch_threads.emplace_back([&s] {
      // Lower priority (Linux: per thread), so that on a busy machine the scheduler runs a
      // robot's request before the next slice of a batch. Failing to lower it is harmless.
      (void)::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 10);
      s.batch_io.run();
    });
  }
}

void Service::run_until_signalled() {
  Impl& s = *impl_;
  asio::signal_set signals(s.io, SIGINT, SIGTERM, SIGHUP);
  std::promise<void> stop_requested;
  std::function<void(const boost::system::error_code&, int)> on_signal =
      [&](const boost::system::error_code& ec, int signal) {
        if (ec) return;
        if (signal == SIGHUP) {
          s.log_line("SIGHUP: reloading every model");
          asio::post(s.reloader, [this] { impl_->registry.reload(true); });
          signals.async_wait(on_signal);
          return;
        }
        s.log_line(signal == SIGINT ? "SIGINT: stopping" : "SIGTERM: stopping");
        stop_requested.set_value();
      };
  signals.async_wait(on_signal);
  start();
  stop_requested.get_future().wait();
  signals.cancel();
  stop();
}

void Service::stop() {
  Impl& s = *impl_;
  if (s.stopping.exchange(true)) return;
  s.work.reset();
  s.io.stop();  // open connections close when io and their sessions are destroyed
  for (std::thread& t : s.threads) t.join();
  s.threads.clear();
  // A batch still answering finishes (its session waits in io, stopped): then the workers end.
  s.batch_work.reset();
  s.batch_io.stop();
  for (std::thread& t : s.batch_threads) t.join();
  s.batch_threads.clear();
  s.reloader.join();
  boost::system::error_code ec;
  if (s.line_acceptor) s.line_acceptor->close(ec);
  if (s.http_acceptor) s.http_acceptor->close(ec);
  s.audit.flush();
}

int Service::reload(bool force) { return impl_->registry.reload(force); }

ServiceStats Service::stats() const { return impl_->stats(); }

const ModelRegistry& Service::models() const { return impl_->registry; }

}  // namespace vrreg::serve
