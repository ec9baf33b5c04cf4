// SPDX-License-Identifier: Apache-2.0
#include "snippets.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/config.hpp"

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
      "# vrreg_correct(p_sensor_mm): p_sensor_mm = [x, y, z], the point the vision system measured,\n"
      "# sensor frame, mm. Returns [x, y, z, sd]: the position to command, robot base frame, mm, and\n"
      "# its predicted sd in mm (0 when the model's method predicts none). The program halts with a\n"
      "# popup when the service cannot be reached, does not answer within {timeout} s, or refuses the\n"
      "# point (outside the model's support, unknown model, ...): it never moves on a default.\n"
      "def vrreg_correct(p_sensor_mm):\n"
      "  if not socket_open(\"{host}\", {port}, \"vrreg\"):\n"
      "    popup(\"vrreg: no correction service at {where}\", \"vrreg\", error=True, blocking=True)\n"
      "    halt\n"
      "  end\n"
      "{auth}"
      "  socket_send_line(str_cat(str_cat(str_cat(\"{model} \", p_sensor_mm[0]), str_cat(\" \", "
      "p_sensor_mm[1])), str_cat(\" \", p_sensor_mm[2])), \"vrreg\")\n"
      "  reply = socket_read_ascii_float(4, \"vrreg\", {timeout})\n"
      "  socket_close(\"vrreg\")\n"
      "  if reply[0] != 4:\n"
      "    popup(\"vrreg: no answer from the correction service at {where}\", \"vrreg\", "
      "error=True, blocking=True)\n"
      "    halt\n"
      "  end\n"
      "  if reply[4] < 0:\n"
      "    popup(str_cat(\"vrreg: point refused, code \", -reply[4]), \"vrreg\", error=True, "
      "blocking=True)\n"
      "    halt\n"
      "  end\n"
      "  return [reply[1], reply[2], reply[3], reply[4]]\n"
      "end\n",
      fmt::arg("version", version()), fmt::arg("model", o.model), fmt::arg("where", where),
      fmt::arg("host", o.host), fmt::arg("port", o.port), fmt::arg("timeout", o.timeout_s),
      fmt::arg("auth", auth));
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
      "      <ELEMENT Tag=\"Reply\" Type=\"STREAM\" EOS=\"10\" Size=\"128\" Set_Flag=\"998\"/>\n"
      "    </RAW>\n"
      "  </RECEIVE>\n"
      "  <SEND/>\n"
      "</ETHERNETKRL>\n",
      fmt::arg("where", fmt::format("{}:{}", o.host, o.port)), fmt::arg("version", version()),
      fmt::arg("host", o.host), fmt::arg("port", o.port),
      fmt::arg("timeout_ms", static_cast<int>(std::lround(o.timeout_s * 1000))));
}

std::string krl_client(const SnippetOptions& o) {
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
  return fmt::format(
      "&ACCESS RVP\n"
      "DEFFCT BOOL VRREG_CORRECT(P_SENSOR_MM:IN, P_ROBOT_MM:OUT, SD_MM:OUT)\n"
      "; vrreg correction service client (vrreg {version}): model '{model}' at {where}, over\n"
      "; EthernetKRL (configuration vrreg.xml, written beside this file). P_SENSOR_MM: the point\n"
      "; the vision system measured, sensor frame, mm (X, Y, Z). Returns TRUE with P_ROBOT_MM (the\n"
      "; position to command, robot base frame, mm) and SD_MM (its predicted sd, mm; 0 when the\n"
      "; method predicts none). Returns FALSE, P_ROBOT_MM untouched, when the service does not\n"
      "; answer within {timeout} s or refuses the point (SD_MM is then minus the refusal code):\n"
      "; the caller must stop, never move on a default.\n"
      "  DECL FRAME P_SENSOR_MM, P_ROBOT_MM\n"
      "  DECL REAL SD_MM, X, Y, Z, SD\n"
      "  DECL EKI_STATUS RET\n"
      "  DECL STATE_T STAT\n"
      "  DECL INT OFS\n"
      "  DECL CHAR REQ[128], REP[128]\n"
      "  RET = EKI_Init(\"vrreg\")\n"
      "  RET = EKI_Open(\"vrreg\")\n"
      "  $FLAG[998] = FALSE\n"
      "  $TIMER[8] = -{timeout_ms}\n"
      "  $TIMER_STOP[8] = FALSE\n"
      "{auth}"
      "  OFS = 0\n"
      "  SWRITE(REQ[], STAT, OFS, \"{model} %.6f %.6f %.6f%c\", P_SENSOR_MM.X, P_SENSOR_MM.Y, "
      "P_SENSOR_MM.Z, 10)\n"
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
      "  SREAD(REP[], STAT, OFS, \"(%r,%r,%r,%r)\", X, Y, Z, SD)\n"
      "  IF STAT.RET1 <> #CMD_OK THEN\n"
      "    RETURN FALSE\n"
      "  ENDIF\n"
      "  SD_MM = SD\n"
      "  IF SD < 0 THEN\n"
      "    RETURN FALSE\n"
      "  ENDIF\n"
      "  P_ROBOT_MM = P_SENSOR_MM\n"
      "  P_ROBOT_MM.X = X\n"
      "  P_ROBOT_MM.Y = Y\n"
      "  P_ROBOT_MM.Z = Z\n"
      "  RETURN TRUE\n"
      "ENDFCT\n",
      fmt::arg("version", version()), fmt::arg("model", o.model),
      fmt::arg("where", fmt::format("{}:{}", o.host, o.port)), fmt::arg("timeout", o.timeout_s),
      fmt::arg("timeout_ms", static_cast<int>(std::lround(o.timeout_s * 1000))),
      fmt::arg("auth", auth));
}

}  // namespace vrreg::serve
