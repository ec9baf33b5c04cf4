// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/results_csv.hpp"

#include <algorithm>
#include <cmath>

#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"

namespace vrreg::io {
namespace {

std::string config_field(const std::optional<int>& config) {
  return config ? std::to_string(*config) : std::string();
}

// A length in mm with `significant` digits, as the files have always been written ("%.10g").
void put_mm(std::string& out, double length_m, int significant) {
  out += format_general(units::m_to_mm(length_m), significant);
}

void put_mm3(std::string& out, const Points3& points_m, Eigen::Index n, int significant) {
  for (int a = 0; a < 3; ++a) {
    out += ',';
    put_mm(out, points_m(a, n), significant);
  }
}

constexpr const char* kPerTargetHeader =
    "point,config,status,unc_tre_mm,cor_tre_mm,delta_tre_mm,"
    "corrected_robot_x_mm,corrected_robot_y_mm,corrected_robot_z_mm,"
    "correction_x_mm,correction_y_mm,correction_z_mm\n";

// Field models add the predicted sd of each corrected target (docs/field-models.md).
std::string per_target_header(const EvaluateResult& r) {
  std::string header = kPerTargetHeader;
  if (r.correction.predicted_sd_m.size() > 0) header.insert(header.size() - 1, ",predicted_sd_mm");
  if (r.orientation) {  // rigid-body markers: the angle errors [mrad]
    std::string angles = ",unc_angle_mrad,cor_angle_mrad";
    if (r.orientation->correction.predicted_sd_rad.size() > 0) angles += ",predicted_angle_sd_mrad";
    header.insert(header.size() - 1, angles);
  }
  return header;
}

void put_per_target_row(std::string& out, const EvaluateResult& r, std::size_t k) {
  constexpr int kDigits = 10;
  const auto n = static_cast<Eigen::Index>(k);
  out += r.names[k];
  out += ',';
  out += config_field(r.configs[k]);
  out += ',';
  out += to_string(r.correction.stencils[k].status);
  out += ',';
  put_mm(out, r.unc_tre_m[n], kDigits);
  out += ',';
  put_mm(out, r.cor_tre_m[n], kDigits);
  out += ',';
  put_mm(out, r.cor_tre_m[n] - r.unc_tre_m[n], kDigits);
  put_mm3(out, r.correction.corrected_robot_m, n, kDigits);
  put_mm3(out, r.correction.corrections_sensor_m, n, kDigits);
  if (r.correction.predicted_sd_m.size() > 0) {
    out += ',';
    if (std::isfinite(r.correction.predicted_sd_m(n))) put_mm(out, r.correction.predicted_sd_m(n), kDigits);
  }
  if (r.orientation) {
    const OrientationEvaluation& o = *r.orientation;
    out += ',' + format_general(1e3 * o.unc_error_rad(n), kDigits);
    out += ',' + format_general(1e3 * o.cor_error_rad(n), kDigits);
    if (o.correction.predicted_sd_rad.size() > 0) {
      out += ',';
      if (std::isfinite(o.correction.predicted_sd_rad(n)))
        out += format_general(1e3 * o.correction.predicted_sd_rad(n), kDigits);
    }
  }
  out += '\n';
}

// Rows per piece written: a few hundred kB at a time, never the whole file in memory.
constexpr std::size_t kRowsPerPiece = 4096;

// Writes `header` then `rows` rows with put_row(piece, k), kRowsPerPiece rows at a time.
template <class PutRow>
void write_rows_in_pieces(const std::string& path, const std::string& header, std::size_t rows,
                          PutRow put_row) {
  std::size_t next = 0;
  bool first = true;
  write_file_atomically_in_pieces(path, [&](std::string& piece) {
    if (first) piece += header;
    first = false;
    const std::size_t end = std::min(rows, next + kRowsPerPiece);
    for (; next < end; ++next) put_row(piece, next);
    return next < rows;
  });
}

}  // namespace

std::string format_per_target_csv(const EvaluateResult& r) {
  std::string out = per_target_header(r);
  for (std::size_t k = 0; k < r.names.size(); ++k) put_per_target_row(out, r, k);
  return out;
}

void write_per_target_csv(const std::string& path, const EvaluateResult& result) {
  write_rows_in_pieces(
      path, per_target_header(result), result.names.size(),
      [&](std::string& piece, std::size_t k) { put_per_target_row(piece, result, k); });
}

namespace {

// Rigid-body markers: the corrected orientation (what to command), robot frame, the applied
// rotation and its predicted sd; absent for spheres (their files stay as they were).
std::string orientation_header(const CorrectResult& r) {
  if (!r.orientation) return "";
  return std::string(
             ",orientation_status,robot_qx,robot_qy,robot_qz,robot_qw,rotation_x_mrad,"
             "rotation_y_mrad,rotation_z_mrad") +
         (r.orientation->predicted_sd_rad.size() > 0
              ? ",predicted_angle_sd_mrad,angle_sd_over_limit"
              : "");
}

void put_orientation(std::string& out, const OrientationCorrection& o, std::size_t k, int digits) {
  out += ',';
  out += to_string(o.status[k]);
  const Eigen::Quaterniond q(o.corrected_R_robot_marker[k]);
  for (int i = 0; i < 4; ++i) {  // x, y, z, w
    out += ',';
    out += format_general(q.coeffs()(i), digits);
  }
  const auto n = static_cast<Eigen::Index>(k);
  for (int i = 0; i < 3; ++i) {
    out += ',';
    out += format_general(1e3 * o.corrections_robot_rad(i, n), digits);
  }
  if (o.predicted_sd_rad.size() > 0) {
    out += ',';
    if (std::isfinite(o.predicted_sd_rad(n)))
      out += format_general(1e3 * o.predicted_sd_rad(n), digits);
    out += o.sd_over_limit(k) ? ",1" : ",0";
  }
}

std::string corrected_header(const CorrectResult& r, const std::string& model_name,
                             const std::string& points_name) {
  const TargetCorrection& c = r.correction;
  return "# vrreg correct: model " + model_name + ", points " + points_name + ", interpolation " +
         to_string(c.method_used) + " (" + c.layout +
         ")\n"
         "point,config,status,robot_x_mm,robot_y_mm,robot_z_mm,"
         "uncorrected_robot_x_mm,uncorrected_robot_y_mm,uncorrected_robot_z_mm,"
         "correction_x_mm,correction_y_mm,correction_z_mm" +
         (c.predicted_sd_m.size() > 0 ? std::string(",predicted_sd_mm") : std::string()) +
         orientation_header(r) + "\n";
}

void put_corrected_row(std::string& out, const CorrectResult& r, std::size_t k) {
  constexpr int kDigits = 12;
  const TargetCorrection& c = r.correction;
  const auto n = static_cast<Eigen::Index>(k);
  out += r.names[k];
  out += ',';
  out += config_field(r.configs[k]);
  out += ',';
  out += to_string(c.stencils[k].status);
  put_mm3(out, c.corrected_robot_m, n, kDigits);
  put_mm3(out, c.uncorrected_robot_m, n, kDigits);
  put_mm3(out, c.corrections_sensor_m, n, kDigits);
  if (c.predicted_sd_m.size() > 0) {
    out += ',';
    if (std::isfinite(c.predicted_sd_m(n))) put_mm(out, c.predicted_sd_m(n), kDigits);
  }
  if (r.orientation) put_orientation(out, *r.orientation, k, kDigits);
  out += '\n';
}

}  // namespace

std::string format_corrected_csv(const CorrectResult& r, const std::string& model_name,
                                 const std::string& points_name) {
  std::string out = corrected_header(r, model_name, points_name);
  for (std::size_t k = 0; k < r.names.size(); ++k) put_corrected_row(out, r, k);
  return out;
}

void write_corrected_csv(const std::string& path, const CorrectResult& result,
                         const std::string& model_name, const std::string& points_name) {
  write_rows_in_pieces(
      path, corrected_header(result, model_name, points_name), result.names.size(),
      [&](std::string& piece, std::size_t k) { put_corrected_row(piece, result, k); });
}

}  // namespace vrreg::io
