// SPDX-License-Identifier: Apache-2.0
// One HTTP/1.1 connection (Boost.Beast): requests until the client closes, stays silent longer
// than the idle timeout, or sends what the bounds refuse (header 8 KiB, body max_body_bytes).
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include "http_api.hpp"
#include "service_impl.hpp"

namespace vrreg::serve {
namespace {

namespace beast = boost::beast;
namespace http = beast::http;
using Request = http::request<http::string_body>;
using Response = http::response<http::string_body>;

constexpr std::uint32_t kMaxHeaderBytes = 8192;


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
  if (const auto* refused = std::get_if<PointAnswer>(&parsed)) {
    ++service.refusals;
    return reply(request, http_status(refused->code), answer_json(*refused, nullptr));
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

Response route(Service::Impl& service, const Request& request, const std::string& client) {
  if (!service.authorized(bearer_of(request))) {
    return refusal(request, ReplyCode::kUnauthorized, "Authorization: Bearer <token> required");
  }
  const std::string_view target(request.target().data(), request.target().size());
  if (target == "/v1/correct") {
    if (request.method() != http::verb::post) return refusal(request, ReplyCode::kMalformed, "use POST");
    return correct(service, request, client);
  }
  if (target == "/v1/health" || target == "/v1/ready") {
    if (request.method() != http::verb::get) return refusal(request, ReplyCode::kMalformed, "use GET");
    return reply(request, 200,
                 health_json(service.registry.all(), service.registry.last_errors(),
                             service.audit.error()));
  }
  return reply(request, 404,
               answer_json(PointAnswer::refusal(ReplyCode::kMalformed,
                                                "no such resource (POST /v1/correct, GET /v1/health)"),
                           nullptr));
}

}  // namespace

asio::awaitable<void> http_session(Service::Impl& service, tcp::socket socket) {
  const OpenConnection counted(service.open);
  const std::string client = peer_of(socket);
  boost::system::error_code ec;
  socket.set_option(tcp::no_delay(true), ec);
  beast::tcp_stream stream(std::move(socket));
  beast::flat_buffer buffer;
  for (;;) {
    http::request_parser<http::string_body> parser;
    parser.header_limit(kMaxHeaderBytes);
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
      Request minimal;
      minimal.version(11);
      minimal.keep_alive(false);
      const bool too_big = ec == http::error::body_limit || ec == http::error::header_limit ||
                           ec == http::error::buffer_overflow;
      ++service.refusals;
      response = refusal(minimal, too_big ? ReplyCode::kLimit : ReplyCode::kMalformed,
                         too_big ? "request too large" : "malformed HTTP request: " + ec.message());
      close = true;
    } else {
      const Request& request = parser.get();
      response = route(service, request, client);
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
