// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the line protocol's request handling end to end (vrreg serve --listen): each input
// line goes through the handler a connection runs (length bound, token, parser, model lookup,
// correction, extrapolation cap, audit log, counters) against small served models
// (serve_fixture.hpp), without the socket. Every reply must be one line a controller reads, with
// as many numbers as the request's form asks, and never an internal error.
#include <string_view>

#include "fuzz_support.hpp"
#include "serve/line_protocol.hpp"
#include "serve_fixture.hpp"

namespace vrreg::fuzz {

int serve_line_handler(const std::uint8_t* data, std::size_t size) {
  const std::string text = as_text(data, size);
  // A connection that starts with "auth" talks to the service that has a token.
  const bool guarded = text.rfind("auth", 0) == 0;
  serve::Service::Impl& service = guarded ? served().guarded() : served().open();
  serve::LineState state;
  state.authorized = !guarded;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();  // the last line, as if its '\n' came
    const std::string_view line(text.data() + start, end - start);
    start = end + 1;
    serve::LineOutcome outcome;
    try {
      outcome = serve::handle_line(service, line, state, "fuzz:1");
    } catch (const std::exception& e) {
      throw Finding(std::string("line handler threw: ") + e.what());
    }
    if (outcome.reply == serve::line_auth_accepted()) {
      require(state.authorized && !outcome.close, "line handler: (1) without authorizing");
      continue;
    }
    const std::vector<double> n = reply_numbers(outcome.reply, "line handler");
    const double code = n.size() == 4 ? -n[3] : -n[n.size() - 2];
    const bool refused = code > 0;
    if (refused) {
      require(code == std::floor(code) && code >= 1 && code <= 8,
              "line handler: an unknown refusal code: " + outcome.reply);
      require(code != 7, "line handler: an internal error: " + outcome.reply);
      require((code == 5 || code == 6) == outcome.close,
              "line handler: only codes 5 and 6 close the connection: " + outcome.reply);
    } else {
      require(!outcome.close, "line handler: an answer that closes the connection");
      require(n.size() == 4 || n.size() == 8 || n.size() == 9,
              "line handler: an answer with a count of numbers no form has: " + outcome.reply);
      require(n[n.size() == 4 ? 3 : n.size() - 2] >= 0, "line handler: a negative sd answered");
    }
    // The form of the reply is the request's (the first orientation keyword decides).
    const serve::LineRequest parsed = serve::parse_line_request(line);
    serve::OrientationForm form = serve::OrientationForm::kNone;
    if (const auto* p = std::get_if<serve::PointRequest>(&parsed)) form = p->orientation_form;
    if (const auto* b = std::get_if<serve::BadRequest>(&parsed)) form = b->form;
    const std::size_t expected = form == serve::OrientationForm::kNone
                                     ? 4
                                     : 5 + static_cast<std::size_t>(orientation_numbers(form));
    const bool short_form = code == 6;  // a bound: sent before the request is read
    require(n.size() == expected || (short_form && n.size() == 4),
            "line handler: a reply in another form than the request's: " + outcome.reply);
    if (outcome.close) break;
  }
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::serve_line_handler)
