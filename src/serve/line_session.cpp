// SPDX-License-Identifier: Apache-2.0
// One line-protocol connection: read a line, answer it, until the client closes, stays silent
// longer than the idle timeout, sends a line longer than the limit, or fails to authenticate.
#include "line_protocol.hpp"
#include "service_impl.hpp"

namespace vrreg::serve {

// One connection's socket and what its watchdog needs, shared by the session and the watchdog
// (both on the connection's strand, so never at once).
struct LineConnection {  // not in an anonymous namespace: the session coroutine's frame holds one
  explicit LineConnection(tcp::socket s) : socket(std::move(s)), timer(socket.get_executor()) {}
  tcp::socket socket;
  asio::steady_timer timer;
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
  bool writing = false;  ///< a reply is waiting for the client to read
};

// Closes the connection when it has been silent longer than the idle timeout, or a reply has
// waited longer than the io timeout to go out (a client that never reads is dropped). One timer
// per connection, checking a few times per timeout, rather than a timer armed per request: arming
// one costs system calls on every request, and a request takes microseconds.
static asio::awaitable<void> watchdog(Service::Impl& service, std::shared_ptr<LineConnection> c) {
  boost::system::error_code ec;
  const double period_s =
      std::min(service.options.idle_timeout_s, service.options.io_timeout_s) / 4.0;
  while (c->socket.is_open()) {
    c->timer.expires_after(after_seconds(period_s));
    co_await c->timer.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    if (ec || !c->socket.is_open()) break;
    const auto silent = std::chrono::steady_clock::now() - c->last;
    const bool idle = !c->writing && silent > after_seconds(service.options.idle_timeout_s);
    const bool stuck = c->writing && silent > after_seconds(service.options.io_timeout_s);
    if (idle || stuck) c->socket.close(ec);  // the session's read or write ends with an error
  }
}

// Sends `reply`: at once when the socket takes it (nearly always: a reply is under 100 bytes),
// else waiting for the client to read, under the watchdog's io timeout.
static asio::awaitable<void> send(LineConnection& c, const std::string& reply, boost::system::error_code& ec) {
  std::size_t sent = c.socket.write_some(asio::buffer(reply), ec);
  if (ec == asio::error::would_block || ec == asio::error::try_again) {
    ec.clear();
    sent = 0;
  }
  if (ec || sent == reply.size()) co_return;
  c.writing = true;
  c.last = std::chrono::steady_clock::now();
  co_await asio::async_write(c.socket, asio::buffer(reply.data() + sent, reply.size() - sent),
                             asio::redirect_error(asio::use_awaitable, ec));
  c.writing = false;
}

LineOutcome handle_line(Service::Impl& service, std::string_view line, LineState& state,
                        const std::string& client) {
  // The bound is on the request, whichever line end the client sends; the parser drops the one
  // '\r' of a "\r\n" itself (dropping it here too would take "1\r\r\n" for "1").
  std::string_view request_text = line;
  if (!request_text.empty() && request_text.back() == '\r') request_text.remove_suffix(1);
  if (request_text.size() > service.options.max_line_bytes) {
    service.refused_request(
        client, "line", ReplyCode::kLimit,
        "line over " + std::to_string(service.options.max_line_bytes) + " bytes");
    return {format_line_reply(PointAnswer::refusal(ReplyCode::kLimit, "line too long")), true};
  }
  const LineRequest request = parse_line_request(line);
  if (const auto* auth = std::get_if<AuthRequest>(&request)) {
    state.authorized = service.authorized(auth->token);
    if (state.authorized) return {line_auth_accepted(), false};
    service.refused_request(client, "line", ReplyCode::kUnauthorized, "wrong token");
    return {format_line_reply(PointAnswer::refusal(ReplyCode::kUnauthorized, "")), true};
  }
  if (!state.authorized) {
    const auto* point = std::get_if<PointRequest>(&request);
    const auto* bad = std::get_if<BadRequest>(&request);
    service.refused_request(client, "line", ReplyCode::kUnauthorized,
                            "a request before 'auth <token>'");
    return {format_line_reply(
                PointAnswer::refusal(ReplyCode::kUnauthorized, ""),
                point ? point->orientation_form : (bad ? bad->form : OrientationForm::kNone)),
            true};
  }
  if (const auto* point = std::get_if<PointRequest>(&request)) {
    return {format_line_reply(
                service.answer(service.registry.find(point->model), *point, client, "line"),
                point->orientation_form),
            false};
  }
  const auto& bad = std::get<BadRequest>(request);
  service.refused_request(client, "line", bad.code, bad.reason);
  return {format_line_reply(PointAnswer::refusal(bad.code, bad.reason), bad.form), false};
}

asio::awaitable<void> line_session(Service::Impl& service, tcp::socket socket) {
  const OpenConnection counted(service.open_line);
  const std::string client = peer_of(socket);
  boost::system::error_code ec;
  socket.set_option(tcp::no_delay(true), ec);
  socket.non_blocking(true, ec);
  auto c = std::make_shared<LineConnection>(std::move(socket));
  asio::co_spawn(c->socket.get_executor(), watchdog(service, c), asio::detached);
  std::string buffer;
  LineState state;
  state.authorized = service.options.token.empty();
  // Room for the longest request and its "\r\n": the bound itself is checked on the request.
  const std::size_t max_buffer = service.options.max_line_bytes + 2;
  for (;;) {
    const std::size_t n =
        co_await asio::async_read_until(c->socket, asio::dynamic_buffer(buffer, max_buffer), '\n',
                                        asio::redirect_error(asio::use_awaitable, ec));
    c->last = std::chrono::steady_clock::now();
    LineOutcome outcome;
    if (ec == asio::error::not_found) {  // the line is longer than the bound: no resync, close
      service.refused_request(
          client, "line", ReplyCode::kLimit,
          "line over " + std::to_string(service.options.max_line_bytes) + " bytes");
      outcome = {format_line_reply(PointAnswer::refusal(ReplyCode::kLimit, "line too long")), true};
    } else if (ec) {
      break;  // closed by the client, reset, or by the watchdog
    } else {
      outcome = handle_line(service, std::string_view(buffer.data(), n - 1), state, client);
      buffer.erase(0, n);
    }
    co_await send(*c, outcome.reply, ec);
    if (ec || outcome.close) break;
  }
  c->timer.cancel();
  c->socket.shutdown(tcp::socket::shutdown_both, ec);
  c->socket.close(ec);
}

}  // namespace vrreg::serve
