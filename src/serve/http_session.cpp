// SPDX-License-Identifier: Apache-2.0
// One HTTP/1.1 connection (Boost.Beast): requests until the client closes, stays silent longer
// than the idle timeout, or sends what the bounds refuse (header 8 KiB, body max_body_bytes).
#include "http_api.hpp"
#include "http_handler.hpp"

namespace vrreg::serve {
namespace {

namespace beast = boost::beast;
namespace http = beast::http;
using Request = HttpRequest;
using Response = HttpResponse;

// A single point's body is a few hundred bytes; reading a larger one (or any batch) on an I/O
// thread would hold up the line protocol.
constexpr std::size_t kInlineBodyBytes = 2048;

Response reply(const Request& request, int status, std::string body,
               const char* type = "application/json") {
  Response r{static_cast<http::status>(status), request.version()};
  r.set(http::field::server, "vrreg");
  r.set(http::field::content_type, type);
  r.set(http::field::cache_control, "no-store");
  r.keep_alive(request.keep_alive());
  r.body() = std::move(body);
  r.prepare_payload();
  return r;
}

Response refusal(const Request& request, ReplyCode code, const std::string& reason) {
  return reply(request, http_status(code), answer_json(PointAnswer::refusal(code, reason), nullptr));
}

// A refusal before any point was read: counted, logged and audited.
Response refused(Service::Impl& service, const Request& request, const std::string& client,
                 ReplyCode code, const std::string& reason) {
  service.refused_request(client, "http", code, reason);
  return refusal(request, code, reason);
}

std::string bearer_of(const Request& request) {
  const auto it = request.find(http::field::authorization);
  if (it == request.end()) return {};
  const std::string_view value(it->value().data(), it->value().size());
  constexpr std::string_view kBearer = "Bearer ";
  return value.substr(0, kBearer.size()) == kBearer ? std::string(value.substr(kBearer.size()))
                                                    : std::string();
}

Response correct(Service::Impl& service, const Request& request, const std::string& client) {
  auto parsed = parse_http_correct(request.body(), service.options.max_batch);
  if (const auto* bad = std::get_if<PointAnswer>(&parsed)) {
    service.refused_request(client, "http", bad->code, bad->reason);
    return reply(request, http_status(bad->code), answer_json(*bad, nullptr));
  }
  const HttpCorrectRequest& r = std::get<HttpCorrectRequest>(parsed);
  // The model current now answers the whole request, even if a reload swaps it meanwhile.
  const std::shared_ptr<const ServedModel> model = service.registry.find(r.points.front().model);
  std::vector<PointAnswer> answers;
  answers.reserve(r.points.size());
  for (const PointRequest& p : r.points) answers.push_back(service.answer(model, p, client, "http"));
  if (r.batch && model) return reply(request, 200, batch_json(answers, model->identity()));
  const PointAnswer& a = answers.front();  // one point, or a batch for an unknown model
  return reply(request, http_status(a.code),
               answer_json(a, model && !r.batch ? &model->identity() : nullptr));
}

// A named coroutine, not a lambda: the session's frame may hold only types with linkage.
asio::awaitable<Response> answer_on_worker(Service::Impl& service, const Request& request,
                                           const std::string& client);

}  // namespace

Response handle_http(Service::Impl& service, const Request& request, const std::string& client) {
  try {
    const std::string_view target(request.target().data(), request.target().size());
    // Liveness says only that the process answers: no token, nothing about models or files.
    if (target == "/v1/live") {
      if (request.method() != http::verb::get) {
        return refused(service, request, client, ReplyCode::kMalformed, "use GET");
      }
      return reply(request, 200, R"({"status":"live"})");
    }
    if (!service.authorized(bearer_of(request))) {
      return refused(service, request, client, ReplyCode::kUnauthorized,
                     "Authorization: Bearer <token> required");
    }
    if (target == "/v1/correct") {
      if (request.method() != http::verb::post) {
        return refused(service, request, client, ReplyCode::kMalformed, "use POST");
      }
      return correct(service, request, client);
    }
    if (target == "/v1/health" || target == "/v1/ready") {
      if (request.method() != http::verb::get) {
        return refused(service, request, client, ReplyCode::kMalformed, "use GET");
      }
      return reply(request, 200,
                   health_json(service.registry.all(), service.registry.last_errors(),
                               service.audit.error(), service.stats()));
    }
    service.refused_request(client, "http", ReplyCode::kMalformed, "no such resource");
    return reply(
        request, 404,
        answer_json(PointAnswer::refusal(
                        ReplyCode::kMalformed,
                        "no such resource (POST /v1/correct, GET /v1/health, GET /v1/live)"),
                    nullptr));
  } catch (const std::exception& e) {  // a bug: said, never a dropped connection
    return refusal(request, ReplyCode::kInternal, e.what());
  }
}

Response refuse_unreadable_http(Service::Impl& service, const beast::error_code& error,
                                const std::string& client) {
  Request minimal;
  minimal.version(11);
  minimal.keep_alive(false);
  const bool too_big = error == http::error::body_limit || error == http::error::header_limit ||
                       error == http::error::buffer_overflow;
  return refused(service, minimal, client, too_big ? ReplyCode::kLimit : ReplyCode::kMalformed,
                 too_big ? "request too large" : "malformed HTTP request: " + error.message());
}

bool answered_on_batch_workers(const Service::Impl& service, const Request& request) {
  if (request.method() != http::verb::post || request.target() != "/v1/correct") return false;
  if (request.body().size() > kInlineBodyBytes) return true;
  const auto parsed = parse_http_correct(request.body(), service.options.max_batch);
  const auto* r = std::get_if<HttpCorrectRequest>(&parsed);
  return r != nullptr && r->batch;
}

namespace {

asio::awaitable<Response> answer_on_worker(Service::Impl& service, const Request& request,
                                           const std::string& client) {
  co_return handle_http(service, request, client);
}

}  // namespace

asio::awaitable<void> http_session(Service::Impl& service, tcp::socket socket) {
  const OpenConnection counted(service.open_http);
  const std::string client = peer_of(socket);
  boost::system::error_code ec;
  socket.set_option(tcp::no_delay(true), ec);
  beast::tcp_stream stream(std::move(socket));
  beast::flat_buffer buffer;
  for (;;) {
    http::request_parser<http::string_body> parser;
    parser.header_limit(kMaxHttpHeaderBytes);
    parser.body_limit(service.options.max_body_bytes);
    stream.expires_after(after_seconds(service.options.idle_timeout_s));
    co_await http::async_read(stream, buffer, parser, asio::redirect_error(asio::use_awaitable, ec));
    if (ec == http::error::end_of_stream || ec == beast::error::timeout ||
        ec == asio::error::eof || ec == asio::error::connection_reset) {
      break;
    }
    std::optional<Response> response;
    bool close = false;
    if (ec) {  // a malformed or oversized request: say why, then close (no resync)
      response = refuse_unreadable_http(service, ec, client);
      close = true;
    } else {
      const Request& request = parser.get();
      if (answered_on_batch_workers(service, request)) {
        // Off the I/O threads; this session resumes on its own strand when the batch is done.
        response = co_await asio::co_spawn(
            service.batch_io, answer_on_worker(service, request, client), asio::use_awaitable);
      } else {
        response = handle_http(service, request, client);
      }
      close = !request.keep_alive() || response->result_int() == 401;
      if (close) response->keep_alive(false);
    }
    stream.expires_after(after_seconds(service.options.io_timeout_s));
    co_await http::async_write(stream, *response, asio::redirect_error(asio::use_awaitable, ec));
    if (ec || close) break;
  }
  stream.socket().shutdown(tcp::socket::shutdown_both, ec);
  stream.close();
}

}  // namespace vrreg::serve
