// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the HTTP requests' handling end to end (vrreg serve --http): Beast's parser with
// the service's bounds, then the handler a connection runs (liveness, token, route, correction of
// one point or a batch, health, audit log, counters) against small served models
// (serve_fixture.hpp), without the socket. An input that starts with an HTTP method is a whole
// request to the service that has a token (Authorization: Bearer fuzz-token-0123456789); any
// other input is the body of a POST /v1/correct to the service without one. Every reply must be
// one of the documented statuses with a one-line JSON body, never an internal error.
#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "serve/http_api.hpp"
#include "serve/http_handler.hpp"
#include "serve_fixture.hpp"

namespace vrreg::fuzz {
namespace {

namespace http = boost::beast::http;

bool starts_with_method(const std::string& text) {
  for (const char* m : {"GET ", "POST ", "PUT ", "DELETE ", "HEAD ", "OPTIONS ", "PATCH "}) {
    if (text.rfind(m, 0) == 0) return true;
  }
  return false;
}

void check(const serve::HttpResponse& r, const serve::HttpRequest* request) {
  const int status = r.result_int();
  require(status == 200 || status == 400 || status == 401 || status == 404 || status == 413 ||
              status == 422,
          "HTTP handler: status " + std::to_string(status) + ": " + r.body());
  require(r.body().find('\n') == std::string::npos, "HTTP handler: a body of several lines");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(r.body());
  } catch (const std::exception& e) {
    throw Finding("HTTP handler: a body that is not JSON: " + r.body());
  }
  require(j.is_object() && (j.contains("status") || j.contains("results")),
          "HTTP handler: a body without a status: " + r.body());
  if (status != 200) {
    require(j.contains("code") && j["code"].is_number_integer() && j["code"] != 0 &&
                j.contains("error"),
            "HTTP handler: a refusal without its code and reason: " + r.body());
    return;
  }
  if (request == nullptr || request->target() != "/v1/correct") return;
  const auto finite = [](const nlohmann::json& a) {
    if (!a.is_array()) return false;
    for (const auto& v : a)
      if (!v.is_number() || !std::isfinite(v.get<double>())) return false;
    return true;
  };
  const auto check_answer = [&](const nlohmann::json& a) {
    require(a.contains("code") && a["code"].is_number_integer(),
            "HTTP handler: an answer without a code");
    require(a["code"] != 7, "HTTP handler: an internal error in a batch: " + a.dump());
    if (a["code"] == 0) {
      require(finite(a["robot_mm"]) && a["robot_mm"].size() == 3 &&
                  a["predicted_sd_mm"].is_number() && a["predicted_sd_mm"].get<double>() >= 0,
              "HTTP handler: an answer without a finite point and sd: " + a.dump());
    }
  };
  if (j.contains("results")) {
    require(j["results"].is_array() && !j["results"].empty(),
            "HTTP handler: an empty batch answered");
    for (const auto& a : j["results"]) check_answer(a);
  } else {
    check_answer(j);
  }
}

}  // namespace

int serve_http_handler(const std::uint8_t* data, std::size_t size) {
  const std::string text = as_text(data, size);
  ServedFixture& fixture = served();
  try {
    if (!starts_with_method(text)) {
      serve::HttpRequest request{http::verb::post, "/v1/correct", 11};
      request.body() = text;
      request.prepare_payload();
      (void)serve::answered_on_batch_workers(fixture.open(), request);
      check(serve::handle_http(fixture.open(), request, "fuzz:1"), &request);
      return 0;
    }
    serve::Service::Impl& service = fixture.guarded();
    // Requests one after another on one connection, as a session reads them.
    boost::beast::flat_buffer buffer;
    std::size_t offset = 0;
    for (int n = 0; n < 8 && offset < text.size(); ++n) {
      http::request_parser<http::string_body> parser;
      parser.header_limit(serve::kMaxHttpHeaderBytes);
      parser.body_limit(service.options.max_body_bytes);
      parser.eager(true);
      boost::beast::error_code ec;
      while (!ec && !parser.is_done() && offset < text.size()) {
        const std::size_t used =
            parser.put(boost::asio::buffer(text.data() + offset, text.size() - offset), ec);
        if (ec == http::error::need_more) ec = {};
        offset += used;
        if (used == 0 && !ec) break;
      }
      if (!ec && !parser.is_done()) parser.put_eof(ec);
      if (ec || !parser.is_done()) {  // what a session answers before it closes
        if (!ec) ec = http::error::partial_message;
        check(serve::refuse_unreadable_http(service, ec, "fuzz:1"), nullptr);
        break;
      }
      const serve::HttpRequest& request = parser.get();
      (void)serve::answered_on_batch_workers(service, request);
      const serve::HttpResponse response = serve::handle_http(service, request, "fuzz:1");
      check(response, &request);
      if (!request.keep_alive() || response.result_int() == 401) break;
    }
  } catch (const Finding&) {
    throw;
  } catch (const std::exception& e) {
    throw Finding(std::string("HTTP handler threw: ") + e.what());
  }
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::serve_http_handler)
