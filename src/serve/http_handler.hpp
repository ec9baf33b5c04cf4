// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to the service: the HTTP requests' handling apart from the socket, so that the
// sessions and the end-to-end fuzz harness (tests/fuzz/fuzz_serve_handlers.cpp) run the same code.
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <string>

#include "service_impl.hpp"

namespace vrreg::serve {

using HttpRequest = boost::beast::http::request<boost::beast::http::string_body>;
using HttpResponse = boost::beast::http::response<boost::beast::http::string_body>;

/// The HTTP header bound (docs/serve.md).
constexpr std::uint32_t kMaxHttpHeaderBytes = 8192;

/// Answers one request (token, route, correction, health, liveness): counts, logs and audits.
/// Never throws.
HttpResponse handle_http(Service::Impl& service, const HttpRequest& request,
                         const std::string& client);

/// The reply to a request the HTTP parser refused (`error`), which closes the connection.
HttpResponse refuse_unreadable_http(Service::Impl& service, const boost::beast::error_code& error,
                                    const std::string& client);

/// Whether `request` is answered on the batch workers: a batch, or a correction body too large
/// to read on the threads the robots wait on.
bool answered_on_batch_workers(const Service::Impl& service, const HttpRequest& request);

}  // namespace vrreg::serve
