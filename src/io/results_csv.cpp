#include "vrreg/io/results_csv.hpp"

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

}  // namespace

std::string format_per_target_csv(const EvaluateResult& r) {
  constexpr int kDigits = 10;
  std::string out =
      "point,config,status,unc_tre_mm,cor_tre_mm,delta_tre_mm,"
      "corrected_robot_x_mm,corrected_robot_y_mm,corrected_robot_z_mm,"
      "correction_x_mm,correction_y_mm,correction_z_mm\n";
  for (std::size_t k = 0; k < r.names.size(); ++k) {
    const auto n = static_cast<Eigen::Index>(k);
    out += r.names[k] + ',' + config_field(r.configs[k]) + ',' +
           to_string(r.correction.stencils[k].status) + ',';
    put_mm(out, r.unc_tre_m[n], kDigits);
    out += ',';
    put_mm(out, r.cor_tre_m[n], kDigits);
    out += ',';
    put_mm(out, r.cor_tre_m[n] - r.unc_tre_m[n], kDigits);
    put_mm3(out, r.correction.corrected_robot_m, n, kDigits);
    put_mm3(out, r.correction.corrections_sensor_m, n, kDigits);
    out += '\n';
  }
  return out;
}

void write_per_target_csv(const std::string& path, const EvaluateResult& result) {
  write_file_atomically(path, format_per_target_csv(result));
}

std::string format_corrected_csv(const CorrectResult& r, const std::string& model_name,
                                 const std::string& points_name) {
  constexpr int kDigits = 12;
  const TargetCorrection& c = r.correction;
  std::string out = "# vrreg correct: model " + model_name + ", points " + points_name +
                    ", interpolation " + to_string(c.method_used) + " (" + c.layout + ")\n";
  out +=
      "point,config,status,robot_x_mm,robot_y_mm,robot_z_mm,"
      "uncorrected_robot_x_mm,uncorrected_robot_y_mm,uncorrected_robot_z_mm,"
      "correction_x_mm,correction_y_mm,correction_z_mm\n";
  for (std::size_t k = 0; k < r.names.size(); ++k) {
    const auto n = static_cast<Eigen::Index>(k);
    out += r.names[k] + ',' + config_field(r.configs[k]) + ',' + to_string(c.stencils[k].status);
    put_mm3(out, c.corrected_robot_m, n, kDigits);
    put_mm3(out, c.uncorrected_robot_m, n, kDigits);
    put_mm3(out, c.corrections_sensor_m, n, kDigits);
    out += '\n';
  }
  return out;
}

void write_corrected_csv(const std::string& path, const CorrectResult& result,
                         const std::string& model_name, const std::string& points_name) {
  write_file_atomically(path, format_corrected_csv(result, model_name, points_name));
}

}  // namespace vrreg::io
