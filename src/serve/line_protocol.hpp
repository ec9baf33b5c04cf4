// SPDX-License-Identifier: Apache-2.0
#pragma once
// The line protocol a robot controller speaks (docs/serve.md): one ASCII request per line,
//   <model> <x_mm> <y_mm> <z_mm> [config <label>] [joints <q1_rad> ... <qN_rad>] [extrapolate]
// (fields separated by spaces, tabs or commas), one reply line URScript's socket_read_ascii_float
// reads: "(x_mm,y_mm,z_mm,sd_mm)", or "(0,0,0,-code)" when refused; and, when the service needs a
// token, "auth <token>" first, answered "(1)".
#include <string>
#include <string_view>
#include <variant>

#include "request.hpp"

namespace vrreg::serve {

/// "auth <token>".
struct AuthRequest {
  std::string token;
};

/// A request that could not be read: the refusal to send.
struct BadRequest {
  ReplyCode code = ReplyCode::kMalformed;
  std::string reason;
};

using LineRequest = std::variant<PointRequest, AuthRequest, BadRequest>;

/// Reads one request line (without its '\n'; a trailing '\r' is ignored). Never throws.
LineRequest parse_line_request(std::string_view line);

/// The reply line, '\n' included: numbers as `vrreg correct` writes them (12 significant digits).
std::string format_line_reply(const PointAnswer& answer);

/// The reply to an accepted "auth" line.
std::string line_auth_accepted();

/// A length [mm] as the service prints it: 12 significant digits as `vrreg correct`'s CSV, in
/// fixed notation when that would need an exponent (|v| < 1e-4), which a controller may not read.
std::string format_reply_mm(double value_mm);

}  // namespace vrreg::serve
