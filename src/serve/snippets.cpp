// SPDX-License-Identifier: Apache-2.0
#include "snippets.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>
#include <vector>

#include "vrreg/config.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg::serve {

void SnippetOptions::validate() const {
  VRREG_THROW_UNLESS(!model.empty() && model.size() <= 64, "--model: the served model's name");
  for (const char c : model) {
    VRREG_THROW_UNLESS(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.',
                       "--model '" << model << "': letters, digits, '_', '-', '.'");
  }
  for (const char c : host) {
    VRREG_THROW_UNLESS(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == ':',
                       "--connect '" << host << "': an IP address or host name");
  }
  VRREG_THROW_UNLESS(n_joints >= 0 && n_joints <= 16, "the model's robot: 0 to 16 joints");
  VRREG_THROW_UNLESS(!host.empty(), "--connect: no host");
  VRREG_THROW_UNLESS(port > 0, "--connect: the service's port (1 to 65535)");
  VRREG_THROW_UNLESS(std::isfinite(timeout_s) && timeout_s > 0 && timeout_s <= 60,
                     "--timeout-s: above 0, at most 60");
  for (const char c : token) {
    VRREG_THROW_UNLESS(c > 0x20 && c < 0x7f && c != '"' && c != '\\',
                       "token: printable ASCII without spaces, quotes or backslashes");
  }
}

std::string urscript_request_line(const SnippetOptions& options, const std::string& x,
                                  const std::string& y, const std::string& z) {
  return options.model + " " + x + " " + y + " " + z + "\n";
}

std::string urscript_pose_request_line(const SnippetOptions& options,
                                       const std::array<std::string, 6>& pose) {
  return options.model + " " + pose[0] + " " + pose[1] + " " + pose[2] + " rotvec " + pose[3] +
         " " + pose[4] + " " + pose[5] + "\n";
}

std::string urscript_joints_request_line(const SnippetOptions& options,
                                         const std::array<std::string, 3>& xyz,
                                         const std::vector<std::string>& q,
                                         const std::vector<std::string>& q_from) {
  std::string line = options.model + " " + xyz[0] + " " + xyz[1] + " " + xyz[2] + " joints";
  for (const std::string& v : q) line += " " + v;
  line += " from";
  for (const std::string& v : q_from) line += " " + v;
  return line + "\n";
}

namespace {

// URScript's str_cat takes two arguments: the parts concatenated by nesting it.
std::string str_cat_all(std::vector<std::string> parts) {
  while (parts.size() > 1) {
    std::vector<std::string> next;
    for (std::size_t i = 0; i + 1 < parts.size(); i += 2) {
      next.push_back("str_cat(" + parts[i] + ", " + parts[i + 1] + ")");
    }
    if (parts.size() % 2 == 1) next.push_back(parts.back());
    parts = std::move(next);
  }
  return parts.front();
}

// The URScript expression of element `i` of `p_sensor_mm` as vrreg_text writes it.
std::string urscript_number(int i) {
  int scale = 1;
  for (int k = 0; k < (i < 3 ? kUrscriptMmDecimals : kUrscriptRadDecimals); ++k) scale *= 10;
  return fmt::format("vrreg_text(p_sensor_mm[{}], {})", i, scale);
}

// The URScript expression of the request line for the list `p` (3 numbers, or 6 with "rotvec").
std::string urscript_request_expression(const std::string& model, bool pose) {
  std::vector<std::string> parts = {
      "\"" + model + " \"", urscript_number(0), "\" \"", urscript_number(1), "\" \"",
      urscript_number(2)};
  if (pose) {
    for (const std::string& more :
         {std::string("\" rotvec \""), urscript_number(3), std::string("\" \""), urscript_number(4),
          std::string("\" \""), urscript_number(5)}) {
      parts.push_back(more);
    }
  }
  return str_cat_all(parts);
}

// The URScript expression of the request line with the commanded joints `q` and those the robot
// comes from, `q_from` (lists of n_joints angles, rad).
std::string urscript_joints_request_expression(const std::string& model, int n_joints) {
  std::vector<std::string> parts = {
      "\"" + model + " \"", urscript_number(0), "\" \"", urscript_number(1), "\" \"",
      urscript_number(2)};
  int scale = 1;
  for (int k = 0; k < kUrscriptRadDecimals; ++k) scale *= 10;
  for (const char* list : {"q", "q_from"}) {
    parts.push_back(std::string(list) == "q" ? "\" joints\"" : "\" from\"");
    for (int j = 0; j < n_joints; ++j) {
      parts.push_back("\" \"");
      parts.push_back(fmt::format("vrreg_text({}[{}], {})", list, j, scale));
    }
  }
  return str_cat_all(parts);
}

// vrreg_correct_joints, when the model's answers need the joints.
std::string urscript_joints_function(const SnippetOptions& o) {
  if (o.n_joints == 0) return "";
  return fmt::format(
      "# vrreg_correct_joints(p_sensor_mm, q, q_from): as vrreg_correct, for this model, whose\n"
      "# answers need the joints: q = the {n} joints commanded at the point, q_from = those the\n"
      "# robot comes from (the previous commanded point; get_target_joint_positions() just before\n"
      "# the move), rad. The service takes each joint's approach direction from q - q_from (lost\n"
      "# motion leaves a joint short of its command against the direction it arrived from).\n"
      "def vrreg_correct_joints(p_sensor_mm, q, q_from):\n"
      "  reply = vrreg_ask({request}, 4)\n"
      "  if reply[4] < 0:\n"
      "    popup(str_cat(\"vrreg: point refused, code \", -reply[4]), \"vrreg\", error=True, "
      "blocking=True)\n"
      "    halt\n"
      "  end\n"
      "  return [reply[1], reply[2], reply[3], reply[4]]\n"
      "end\n",
      fmt::arg("n", o.n_joints),
      fmt::arg("request", urscript_joints_request_expression(o.model, o.n_joints)));
}

}  // namespace

std::string urscript_client(const SnippetOptions& o) {
  o.validate();
  const std::string where = fmt::format("{}:{}", o.host, o.port);
  std::string auth;
  if (!o.token.empty()) {
    auth = fmt::format(
        "  socket_send_line(\"auth {}\", \"vrreg\")\n"
        "  accepted = socket_read_ascii_float(1, \"vrreg\", {})\n"
        "  if accepted[0] != 1 or accepted[1] != 1:\n"
        "    socket_close(\"vrreg\")\n"
        "    popup(\"vrreg: the correction service refused the token\", \"vrreg\", error=True, "
        "blocking=True)\n"
        "    halt\n"
        "  end\n",
        o.token, o.timeout_s);
  }
  return fmt::format(
      "# vrreg correction service client (vrreg {version}): model '{model}' at {where}.\n"
      "# Every function halts the program with a popup when the service cannot be reached, does\n"
      "# not answer within {timeout} s, or refuses the request (outside the model's support,\n"
      "# unknown model, ...): it never moves on a default.\n"
      "#\n"
      "# vrreg_correct(p_sensor_mm): p_sensor_mm = [x, y, z], the point the vision system "
      "measured,\n"
      "# sensor frame, mm. Returns [x, y, z, sd]: the position to command, robot base frame, mm, "
      "and\n"
      "# its predicted sd in mm (0 when the model's method predicts none).\n"
      "#\n"
      "# vrreg_correct_pose(p_sensor_mm): p_sensor_mm = [x, y, z, rx, ry, rz], the marker's pose "
      "the\n"
      "# vision system measured, sensor frame (mm; rotation vector, rad), for a model registered\n"
      "# with rigid-body fiducials. Returns [x, y, z, rx, ry, rz, sd, sd_angle]: the pose to\n"
      "# command, robot base frame (mm; rotation vector, rad), the position's predicted sd (mm) "
      "and\n"
      "# the orientation's (mrad), 0 when the method predicts none.\n"
      "# vrreg_pose_m(r): that pose as a URScript pose in metres, for movel / movej.\n"
      "#\n"
      "# vrreg_text(v, scale): v as decimal text to 1/scale: str_cat writes a float to 6\n"
      "# significant digits (10 um at 1000 mm), an int exactly; the requests send mm to\n"
      "# {mm_places} decimals and rotation vectors to {rad_places}.\n"
      "def vrreg_text(v, scale):\n"
      "  sign = \"\"\n"
      "  a = v\n"
      "  if v < 0:\n"
      "    sign = \"-\"\n"
      "    a = -v\n"
      "  end\n"
      "  whole = floor(a)\n"
      "  fraction = floor((a - whole) * scale + 0.5)\n"
      "  if fraction >= scale:\n"
      "    whole = whole + 1\n"
      "    fraction = fraction - scale\n"
      "  end\n"
      "  digits = str_cat(\"\", fraction)\n"
      "  place = 10\n"
      "  while place < scale:\n"
      "    if fraction < place:\n"
      "      digits = str_cat(\"0\", digits)\n"
      "    end\n"
      "    place = place * 10\n"
      "  end\n"
      "  return str_cat(str_cat(sign, whole), str_cat(\".\", digits))\n"
      "end\n"
      "def vrreg_ask(request, n):\n"
      "  if not socket_open(\"{host}\", {port}, \"vrreg\"):\n"
      "    popup(\"vrreg: no correction service at {where}\", \"vrreg\", error=True, "
      "blocking=True)\n"
      "    halt\n"
      "  end\n"
      "{auth}"
      "  socket_send_line(request, \"vrreg\")\n"
      "  reply = socket_read_ascii_float(n, \"vrreg\", {timeout})\n"
      "  socket_close(\"vrreg\")\n"
      "  if reply[0] != n:\n"
      "    popup(\"vrreg: no answer from the correction service at {where}\", \"vrreg\", "
      "error=True, blocking=True)\n"
      "    halt\n"
      "  end\n"
      "  return reply\n"
      "end\n"
      "def vrreg_correct(p_sensor_mm):\n"
      "  reply = vrreg_ask({point_request}, 4)\n"
      "  if reply[4] < 0:\n"
      "    popup(str_cat(\"vrreg: point refused, code \", -reply[4]), \"vrreg\", error=True, "
      "blocking=True)\n"
      "    halt\n"
      "  end\n"
      "  return [reply[1], reply[2], reply[3], reply[4]]\n"
      "end\n"
      "def vrreg_correct_pose(p_sensor_mm):\n"
      "  reply = vrreg_ask({pose_request}, 8)\n"
      "  if reply[7] < 0:\n"
      "    popup(str_cat(\"vrreg: pose refused, code \", -reply[7]), \"vrreg\", error=True, "
      "blocking=True)\n"
      "    halt\n"
      "  end\n"
      "  return [reply[1], reply[2], reply[3], reply[4], reply[5], reply[6], reply[7], reply[8]]\n"
      "end\n"
      "def vrreg_pose_m(r):\n"
      "  return p[r[0] / 1000, r[1] / 1000, r[2] / 1000, r[3], r[4], r[5]]\n"
      "end\n",
      fmt::arg("version", version()), fmt::arg("model", o.model), fmt::arg("where", where),
      fmt::arg("host", o.host), fmt::arg("port", o.port), fmt::arg("timeout", o.timeout_s),
      fmt::arg("auth", auth), fmt::arg("mm_places", kUrscriptMmDecimals),
      fmt::arg("rad_places", kUrscriptRadDecimals),
      fmt::arg("point_request", urscript_request_expression(o.model, false)),
      fmt::arg("pose_request", urscript_request_expression(o.model, true))) +
         urscript_joints_function(o);
}

std::string krl_eki_config(const SnippetOptions& o) {
  o.validate();
  return fmt::format(
      "<!-- vrreg correction service ({where}), EthernetKRL configuration (vrreg {version}).\n"
      "     Copy to C:\\KRC\\ROBOTER\\Config\\User\\Common\\EthernetKRL\\vrreg.xml -->\n"
      "<ETHERNETKRL>\n"
      "  <CONFIGURATION>\n"
      "    <EXTERNAL>\n"
      "      <IP>{host}</IP>\n"
      "      <PORT>{port}</PORT>\n"
      "    </EXTERNAL>\n"
      "    <INTERNAL>\n"
      "      <ENVIRONMENT>Program</ENVIRONMENT>\n"
      "      <BUFFERING Limit=\"1\"/>\n"
      "      <TIMEOUT Connect=\"{timeout_ms}\"/>\n"
      "    </INTERNAL>\n"
      "  </CONFIGURATION>\n"
      "  <RECEIVE>\n"
      "    <RAW>\n"
      "      <ELEMENT Tag=\"Reply\" Type=\"STREAM\" EOS=\"10\" Size=\"256\" Set_Flag=\"998\"/>\n"
      "    </RAW>\n"
      "  </RECEIVE>\n"
      "  <SEND/>\n"
      "</ETHERNETKRL>\n",
      fmt::arg("where", fmt::format("{}:{}", o.host, o.port)), fmt::arg("version", version()),
      fmt::arg("host", o.host), fmt::arg("port", o.port),
      fmt::arg("timeout_ms", static_cast<int>(std::lround(o.timeout_s * 1000))));
}

std::string krl_request_line(const SnippetOptions& options, const std::array<double, 6>& frame,
                             bool pose) {
  // SWRITE's "%.6f", as the KRL function formats X, Y, Z (and A, B, C).
  std::string line =
      fmt::format("{} {:.6f} {:.6f} {:.6f}", options.model, frame[0], frame[1], frame[2]);
  if (pose) line += fmt::format(" abc {:.6f} {:.6f} {:.6f}", frame[3], frame[4], frame[5]);
  return line + "\n";
}

std::string krl_joints_request_line(const SnippetOptions& options,
                                    const std::array<double, 3>& xyz_mm,
                                    const std::vector<double>& q_rad,
                                    const std::vector<double>& q_from_rad) {
  // The KRL function's SWRITEs: "%.6f" for X, Y, Z, then " %.7f" per joint angle (rad).
  std::string line = fmt::format("{} {:.6f} {:.6f} {:.6f} joints", options.model, xyz_mm[0],
                                 xyz_mm[1], xyz_mm[2]);
  for (const double q : q_rad) line += fmt::format(" {:.7f}", q);
  line += " from";
  for (const double q : q_from_rad) line += fmt::format(" {:.7f}", q);
  return line + "\n";
}

namespace {

// KRL names of the joints of an E6AXIS in order: A1..A6, then the external axes E1..E6 (the
// LWR 4+'s seventh joint is E1 on its controller).
std::string krl_axis(int j) {
  return j < 6 ? fmt::format("A{}", j + 1) : fmt::format("E{}", j - 5);
}

// The request of VRREG_CORRECT_JOINTS: each joint converted to rad into Q[] and F[] (SWRITE
// formats values, not expressions), then the line written in pieces at OFS.
std::string krl_joints_send(const SnippetOptions& o) {
  std::string out;
  for (int j = 0; j < o.n_joints; ++j) {
    out += fmt::format("  Q[{0}] = Q_DEG.{1} * DEG_TO_RAD\n  F[{0}] = Q_FROM_DEG.{1} * DEG_TO_RAD\n",
                       j + 1, krl_axis(j));
  }
  out += "  SWRITE(REQ[], STAT, OFS, \"" + o.model +
         " %.6f %.6f %.6f joints\", P_SENSOR_MM.X, P_SENSOR_MM.Y, P_SENSOR_MM.Z)\n";
  for (int j = 0; j < o.n_joints; ++j)
    out += fmt::format("  SWRITE(REQ[], STAT, OFS, \" %.7f\", Q[{}])\n", j + 1);
  out += "  SWRITE(REQ[], STAT, OFS, \" from\")\n";
  for (int j = 0; j < o.n_joints; ++j)
    out += fmt::format("  SWRITE(REQ[], STAT, OFS, \" %.7f\", F[{}])\n", j + 1);
  out += "  SWRITE(REQ[], STAT, OFS, \"%c\", 10)\n";
  return out;
}

enum class KrlKind { kPoint, kPose, kJoints };

std::string krl_function(const SnippetOptions& o, KrlKind kind) {
  const bool pose = kind == KrlKind::kPose;
  const bool joints = kind == KrlKind::kJoints;
  o.validate();
  std::string auth;
  if (!o.token.empty()) {
    auth = fmt::format(
        "  OFS = 0\n"
        "  SWRITE(REQ[], STAT, OFS, \"auth {}%c\", 10)\n"
        "  RET = EKI_Send(\"vrreg\", REQ[])\n"
        "  WAIT FOR $FLAG[998] OR $TIMER_FLAG[8]\n"
        "  IF NOT $FLAG[998] THEN\n"
        "    RET = EKI_Close(\"vrreg\")\n"
        "    RETURN FALSE\n"
        "  ENDIF\n"
        "  $FLAG[998] = FALSE\n"
        "  RET = EKI_GetString(\"vrreg\", \"Reply\", REP[])\n",
        o.token);
  }
  const std::string name = pose     ? "VRREG_CORRECT_POSE"
                           : joints ? "VRREG_CORRECT_JOINTS"
                                    : "VRREG_CORRECT";
  const std::string signature =
      pose     ? "P_SENSOR_MM:IN, P_ROBOT_MM:OUT, SD_MM:OUT, SD_MRAD:OUT"
      : joints ? "P_SENSOR_MM:IN, Q_DEG:IN, Q_FROM_DEG:IN, P_ROBOT_MM:OUT, SD_MM:OUT"
               : "P_SENSOR_MM:IN, P_ROBOT_MM:OUT, SD_MM:OUT";
  const std::string what =
      pose
          ? "; the vision system measured the marker's pose P_SENSOR_MM, sensor frame (X, Y, Z "
            "mm;\n"
            "; A, B, C deg) for a model registered with rigid-body fiducials. Returns TRUE with\n"
            "; P_ROBOT_MM (the pose to command, robot base frame: X, Y, Z mm; A, B, C deg), SD_MM\n"
            "; (its position's predicted sd, mm) and SD_MRAD (its orientation's, mrad; both 0 "
            "when\n"
            "; the method predicts none). Returns FALSE, P_ROBOT_MM untouched, when the service\n"
          : "; P_SENSOR_MM: the point the vision system measured, sensor frame, mm (X, Y, Z).\n" +
                std::string(joints ? fmt::format(
                                         "; Q_DEG: the {} joints commanded at the point, Q_FROM_DEG: "
                                         "those the robot comes from\n"
                                         "; (the previous commanded point), deg (A1..A6{}), sent "
                                         "in rad: the model's answers need them.\n",
                                         o.n_joints, o.n_joints > 6 ? ", then E1.." : "")
                                   : std::string()) +
                "; Returns TRUE with P_ROBOT_MM (the position to command, robot base frame, mm) "
                "and\n"
                "; SD_MM (its predicted sd, mm; 0 when the method predicts none). Returns FALSE,\n"
                "; P_ROBOT_MM untouched, when the service\n";
  const std::string send =
      joints ? krl_joints_send(o)
      : pose ? "  SWRITE(REQ[], STAT, OFS, \"" + o.model +
                 " %.6f %.6f %.6f abc %.6f %.6f %.6f%c\", P_SENSOR_MM.X, P_SENSOR_MM.Y, "
                 "P_SENSOR_MM.Z, P_SENSOR_MM.A, P_SENSOR_MM.B, P_SENSOR_MM.C, 10)\n"
           : "  SWRITE(REQ[], STAT, OFS, \"" + o.model +
                 " %.6f %.6f %.6f%c\", P_SENSOR_MM.X, P_SENSOR_MM.Y, P_SENSOR_MM.Z, 10)\n";
  const std::string read =
      pose ? "  SREAD(REP[], STAT, OFS, \"(%r,%r,%r,%r,%r,%r,%r,%r)\", X, Y, Z, A, B, C, SD, "
             "SD_ANGLE)\n"
           : "  SREAD(REP[], STAT, OFS, \"(%r,%r,%r,%r)\", X, Y, Z, SD)\n";
  const std::string out = pose ? "  SD_MRAD = SD_ANGLE\n"
                                 "  P_ROBOT_MM = P_SENSOR_MM\n"
                                 "  P_ROBOT_MM.X = X\n"
                                 "  P_ROBOT_MM.Y = Y\n"
                                 "  P_ROBOT_MM.Z = Z\n"
                                 "  P_ROBOT_MM.A = A\n"
                                 "  P_ROBOT_MM.B = B\n"
                                 "  P_ROBOT_MM.C = C\n"
                               : "  P_ROBOT_MM = P_SENSOR_MM\n"
                                 "  P_ROBOT_MM.X = X\n"
                                 "  P_ROBOT_MM.Y = Y\n"
                                 "  P_ROBOT_MM.Z = Z\n";
  return fmt::format(
      "&ACCESS RVP\n"
      "DEFFCT BOOL {name}({signature})\n"
      "; vrreg correction service client (vrreg {version}): model '{model}' at {where}, over\n"
      "; EthernetKRL (configuration vrreg.xml, written beside this file).\n"
      "{what}"
      "; does not answer within {timeout} s or refuses the request (SD_MM is then minus the\n"
      "; refusal code): the caller must stop, never move on a default.\n"
      "  DECL FRAME P_SENSOR_MM, P_ROBOT_MM\n"
      "{joints_decl}"
      "  DECL REAL SD_MM{sd_mrad_decl}, X, Y, Z, {abc_decl}SD\n"
      "  DECL EKI_STATUS RET\n"
      "  DECL STATE_T STAT\n"
      "  DECL INT OFS\n"
      "  DECL CHAR REQ[{req_size}], REP[256]\n"
      "  RET = EKI_Init(\"vrreg\")\n"
      "  RET = EKI_Open(\"vrreg\")\n"
      "  $FLAG[998] = FALSE\n"
      "  $TIMER[8] = -{timeout_ms}\n"
      "  $TIMER_STOP[8] = FALSE\n"
      "{auth}"
      "{deg_to_rad}"
      "  OFS = 0\n"
      "{send}"
      "  RET = EKI_Send(\"vrreg\", REQ[])\n"
      "  WAIT FOR $FLAG[998] OR $TIMER_FLAG[8]\n"
      "  $TIMER_STOP[8] = TRUE\n"
      "  IF NOT $FLAG[998] THEN\n"
      "    RET = EKI_Close(\"vrreg\")\n"
      "    RET = EKI_Clear(\"vrreg\")\n"
      "    RETURN FALSE\n"
      "  ENDIF\n"
      "  RET = EKI_GetString(\"vrreg\", \"Reply\", REP[])\n"
      "  RET = EKI_Close(\"vrreg\")\n"
      "  RET = EKI_Clear(\"vrreg\")\n"
      "  OFS = 0\n"
      "{read}"
      "  IF STAT.RET1 <> #CMD_OK THEN\n"
      "    RETURN FALSE\n"
      "  ENDIF\n"
      "  SD_MM = SD\n"
      "  IF SD < 0 THEN\n"
      "    RETURN FALSE\n"
      "  ENDIF\n"
      "{out}"
      "  RETURN TRUE\n"
      "ENDFCT\n",
      fmt::arg("name", name), fmt::arg("signature", signature), fmt::arg("what", what),
      fmt::arg("version", version()), fmt::arg("model", o.model),
      fmt::arg("where", fmt::format("{}:{}", o.host, o.port)), fmt::arg("timeout", o.timeout_s),
      fmt::arg("timeout_ms", static_cast<int>(std::lround(o.timeout_s * 1000))),
      fmt::arg("auth", auth), fmt::arg("send", send), fmt::arg("read", read), fmt::arg("out", out),
      fmt::arg("sd_mrad_decl", pose ? ", SD_MRAD" : ""),
      fmt::arg("joints_decl", joints ? fmt::format("  DECL E6AXIS Q_DEG, Q_FROM_DEG\n"
                                                   "  DECL REAL Q[{0}], F[{0}]\n"
                                                   "  DECL REAL DEG_TO_RAD\n",
                                                   o.n_joints)
                                     : std::string()),
      fmt::arg("req_size", joints ? 512 : 256),
      fmt::arg("deg_to_rad", joints ? "  DEG_TO_RAD = 0.0174532925199433\n" : ""),
      fmt::arg("abc_decl", pose ? "A, B, C, SD_ANGLE, " : ""));
}

}  // namespace

std::string krl_client(const SnippetOptions& o) {
  return krl_function(o, o.n_joints > 0 ? KrlKind::kJoints : KrlKind::kPoint);
}

std::string krl_pose_client(const SnippetOptions& o) {
  VRREG_THROW_UNLESS(o.n_joints == 0,
                     "the pose function sends no joints, and the model's answers need them");
  return krl_function(o, KrlKind::kPose);
}

}  // namespace vrreg::serve
