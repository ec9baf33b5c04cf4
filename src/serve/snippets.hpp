// SPDX-License-Identifier: Apache-2.0
#pragma once
// Robot-side clients of the line protocol: the function a robot program calls to have a point
// corrected by `vrreg serve` (URScript for Universal Robots, KRL with EthernetKRL for KUKA).
#include <array>
#include <string>
#include <vector>

namespace vrreg::serve {

struct SnippetOptions {
  std::string model;           ///< the served model's name
  std::string host = "127.0.0.1";
  unsigned short port = 0;
  double timeout_s = 2.0;      ///< no reply within this: the program stops, never moves
  std::string token;           ///< sent first ("auth <token>") when the service needs one
  /// Joints of the served model's robot when its answers need them (a joint-space model, or one
  /// with a lost-motion term): the program then also has the functions that send the commanded
  /// joints and those the robot comes from; 0: it has not.
  int n_joints = 0;

  /// Throws InputError naming the option.
  void validate() const;
};

/// URScript: `vrreg_correct(p_sensor_mm)` -> [x_mm, y_mm, z_mm, sd_mm], robot base frame, and
/// `vrreg_correct_pose([x, y, z, rx, ry, rz])` -> the pose to command (mm, rotation vector [rad])
/// with the position's sd [mm] and the orientation's [mrad]; both halt with a popup when the
/// service is unreachable, silent, or refuses the request.
std::string urscript_client(const SnippetOptions& options);

/// Decimals of the numbers the URScript functions send (vrreg_text in the program): mm to 0.1 um
/// (the text within 0.05 um of the program's float), rotation vectors to 0.1 urad (within 0.15
/// urad: 32-bit products), near the spacing of URScript's 32-bit floats at a metre (0.12 um) and
/// at pi (0.24 urad); str_cat alone writes 6 significant digits (5 um at 1.3 m).
inline constexpr int kUrscriptMmDecimals = 4;
inline constexpr int kUrscriptRadDecimals = 7;

/// The request lines the URScript functions send, numbers as the program's vrreg_text writes
/// them (what the tests send to the service to check the snippet's bytes).
std::string urscript_request_line(const SnippetOptions& options, const std::string& x,
                                  const std::string& y, const std::string& z);
/// The line `vrreg_correct_joints(p, q, q_from)` sends: the point, `joints` and `from` (rad, as
/// vrreg_text writes them to kUrscriptRadDecimals).
std::string urscript_joints_request_line(const SnippetOptions& options,
                                         const std::array<std::string, 3>& xyz,
                                         const std::vector<std::string>& q,
                                         const std::vector<std::string>& q_from);
std::string urscript_pose_request_line(const SnippetOptions& options,
                                       const std::array<std::string, 6>& pose);

/// KRL: `VRREG_CORRECT(P_SENSOR_MM, P_ROBOT_MM, SD_MM)` (a DEFFCT returning TRUE on an answer)
/// over EthernetKRL, and its EKI configuration (XML) for the controller's Config/User/Common/EthernetKRL.
/// When the model's answers need the joints (options.n_joints > 0) the file's function is
/// `VRREG_CORRECT_JOINTS(P_SENSOR_MM, Q_DEG, Q_FROM_DEG, P_ROBOT_MM, SD_MM)` instead (a KRL file
/// holds the function it is named after): Q_DEG the E6AXIS commanded at the point, Q_FROM_DEG the
/// one the robot comes from (A1..A6 deg, a seventh joint as E1), sent as `joints ... from ...`
/// in rad.
std::string krl_client(const SnippetOptions& options);
/// KRL: `VRREG_CORRECT_POSE(P_SENSOR_MM, P_ROBOT_MM, SD_MM, SD_MRAD)`: the whole FRAME (X, Y, Z
/// mm; A, B, C deg), for models registered with rigid-body fiducials. Throws InputError for a
/// model whose answers need the joints (it sends none).
std::string krl_pose_client(const SnippetOptions& options);
std::string krl_eki_config(const SnippetOptions& options);

/// The request line the KRL function sends for FRAME `frame` (X, Y, Z, A, B, C; A, B, C used
/// when `pose`), numbers as its SWRITE "%.6f" writes them.
std::string krl_request_line(const SnippetOptions& options, const std::array<double, 6>& frame,
                             bool pose);
/// The request line VRREG_CORRECT_JOINTS sends: X, Y, Z as "%.6f", each joint (rad, as the
/// function converts Q_DEG and Q_FROM_DEG) as "%.7f".
std::string krl_joints_request_line(const SnippetOptions& options,
                                    const std::array<double, 3>& xyz_mm,
                                    const std::vector<double>& q_rad,
                                    const std::vector<double>& q_from_rad);

}  // namespace vrreg::serve
