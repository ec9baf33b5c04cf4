// SPDX-License-Identifier: Apache-2.0
#pragma once
// The line protocol a robot controller speaks (docs/serve.md): one ASCII request per line,
//   <model> <x_mm> <y_mm> <z_mm> [config <label>] [joints <q1_rad> ... <qN_rad>] [extrapolate]
//           [rotvec <rx> <ry> <rz> | quat <qx> <qy> <qz> <qw> | abc <a_deg> <b_deg> <c_deg>]
// (fields separated by spaces, tabs or commas), one reply line URScript's socket_read_ascii_float
// reads: "(x_mm,y_mm,z_mm,sd_mm)", or "(0,0,0,-code)" when refused; with an orientation,
// "(x_mm,y_mm,z_mm,<orientation as given>,sd_mm,sd_angle_mrad)", refused with zeros and
// "-code,-code"; and, when the service needs a token, "auth <token>" first, answered "(1)".
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
  OrientationForm form = OrientationForm::kNone;  ///< the reply's form (the request's keyword)
};

using LineRequest = std::variant<PointRequest, AuthRequest, BadRequest>;

/// Reads one request line (without its '\n'; a trailing '\r' is ignored). Never throws.
LineRequest parse_line_request(std::string_view line);

/// The reply line, '\n' included: numbers as `vrreg correct` writes them (12 significant digits);
/// with the corrected orientation in `form` (the request's) when it is not kNone.
std::string format_line_reply(const PointAnswer& answer,
                              OrientationForm form = OrientationForm::kNone);

/// The reply to an accepted "auth" line.
std::string line_auth_accepted();

/// A number as the service prints it: 12 significant digits as `vrreg correct`'s CSV, in fixed
/// notation when that would need an exponent (|v| < 1e-4), which a controller may not read.
std::string format_reply_number(double value);

/// The orientation `q` in `form`: the rotation vector [rad] (|w| <= pi), KUKA's A, B, C [deg],
/// or the quaternion's x, y, z, w with w >= 0.
Eigen::VectorXd orientation_in(const Eigen::Quaterniond& q, OrientationForm form);

}  // namespace vrreg::serve
