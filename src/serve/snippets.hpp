// SPDX-License-Identifier: Apache-2.0
#pragma once
// Robot-side clients of the line protocol: the function a robot program calls to have a point
// corrected by `vrreg serve` (URScript for Universal Robots, KRL with EthernetKRL for KUKA).
#include <string>

namespace vrreg::serve {

struct SnippetOptions {
  std::string model;           ///< the served model's name
  std::string host = "127.0.0.1";
  unsigned short port = 0;
  double timeout_s = 2.0;      ///< no reply within this: the program stops, never moves
  std::string token;           ///< sent first ("auth <token>") when the service needs one

  /// Throws InputError naming the option.
  void validate() const;
};

/// URScript: `vrreg_correct(p_sensor_mm)` -> [x_mm, y_mm, z_mm, sd_mm], robot base frame; halts
/// with a popup when the service is unreachable, silent, or refuses the point.
std::string urscript_client(const SnippetOptions& options);

/// The request line the URScript function sends for a point, as URScript's str_cat writes numbers
/// (what the tests send to the service to check the snippet's bytes).
std::string urscript_request_line(const SnippetOptions& options, const std::string& x,
                                  const std::string& y, const std::string& z);

/// KRL: `VRREG_CORRECT(P_SENSOR_MM, P_ROBOT_MM, SD_MM)` (a DEFFCT returning TRUE on an answer)
/// over EthernetKRL, and its EKI configuration (XML) for the controller's Config/User/Common/EthernetKRL.
std::string krl_client(const SnippetOptions& options);
std::string krl_eki_config(const SnippetOptions& options);

}  // namespace vrreg::serve
