// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/result_json.hpp"

#include <vector>

#include "guard_json.hpp"
#include "lost_motion_json.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/metrics/multidirectional.hpp"
#include "vrreg/metrics/uncertainty_calibration.hpp"

namespace vrreg::io {
namespace {

nlohmann::json mm_or_null(const std::optional<double>& m) {
  return m ? nlohmann::json(units::m_to_mm(*m)) : nlohmann::json(nullptr);
}

// Millimetres with 4 decimals (0.1 um), as the brief reports give lengths.
std::string mm_text(double metres) { return format_mm(metres, 4) + " mm"; }

}  // namespace

nlohmann::json json_mm3(const Eigen::Vector3d& m) {
  return {units::m_to_mm(m.x()), units::m_to_mm(m.y()), units::m_to_mm(m.z())};
}

std::string location_name(const Location& location) {
  return location.point +
         (location.config ? " (config " + std::to_string(*location.config) + ")" : "");
}

nlohmann::json cross_validation_json(const CrossValidation& cv) {
  nlohmann::json j;
  j["folds"] = cv.folds;
  j["seed"] = cv.seed;
  j["chosen"] = to_string(cv.chosen);
  j["n_ranked"] = cv.n_ranked;
  nlohmann::json rows = nlohmann::json::array();
  for (const CrossValidationRow& row : cv.rows) {
    nlohmann::json r;
    r["method"] = to_string(row.method);
    r["applicable"] = row.applicable;
    if (row.applicable) {
      r["rms_ranked_mm"] = units::m_to_mm(row.rms_ranked_m);
      r["rms_mm"] = units::m_to_mm(row.rms_m);
      r["rms_axis_mm"] = json_mm3(row.rms_axis_m);
      r["n_predicted"] = row.n_predicted;
    } else {
      r["note"] = row.note;
    }
    rows.push_back(r);
  }
  j["rows"] = rows;
  return j;
}

nlohmann::json robust_json(const RobustReport& report) {
  const OutlierDetection& d = report.detection;
  nlohmann::json j;
  j["method"] = "leave-one-out affine prediction from neighbours of the same configuration";
  j["judged"] = d.n_judged;
  j["sigma_mm"] = units::m_to_mm(d.sigma_m);
  j["scale"] = d.scale_is_noise ? "sigma_noise" : "spread";
  j["sigma_spread_mm"] = units::m_to_mm(d.sigma_spread_m);
  j["sigma_noise_mm"] = mm_or_null(d.sigma_noise_m);
  j["false_alarm_rate"] = report.false_alarm_rate;
  j["threshold_sigmas"] = d.threshold_sigmas;
  j["outliers"] = nlohmann::json::array();
  for (const RejectedFiducial& r : report.rejected) {
    nlohmann::json o;
    o["point"] = r.point;
    o["config"] = r.config ? nlohmann::json(*r.config) : nlohmann::json(nullptr);
    o["deviation_mm"] = units::m_to_mm(r.deviation_m);
    o["sigmas"] = r.sigmas;
    o["handling"] = r.filled ? "filled from neighbours" : "dropped";
    j["outliers"].push_back(o);
  }
  return j;
}

void add_predicted_sd_json(const TargetCorrection& correction,
                           const std::optional<UncertaintyCalibration>& calibration,
                           nlohmann::json& j) {
  const PredictedSdSummary sd = summarize_predicted_sd(correction.predicted_sd_m);
  if (sd.n == 0) return;
  j["predicted_sd_median_mm"] = units::m_to_mm(sd.median_m);
  j["predicted_sd_max_mm"] = units::m_to_mm(sd.max_m);
  if (calibration && calibration->n > 0) {
    j["calibration"] = {{"n", calibration->n},
                        {"rms_tre_over_sd", calibration->rms_ratio},
                        {"within_2sd", calibration->within_2sigma}};
  }
}

void add_strategy_json(const RegistrationModel& model,
                       const std::optional<planning::Strategy2Summary>& relabelled,
                       nlohmann::json& j) {
  const planning::Procedure2& p = model.procedure2;
  const int strategy = planning::strategy_number(p.strategy);
  j["strategy"] = strategy == 0 ? nlohmann::json(nullptr) : nlohmann::json(strategy);
  if (strategy >= 2) j["joint_norm"] = kinematics::to_string(p.joint_norm);
  if (relabelled) {
    // switched_fraction is the paper's figure (section 5.2: "14 % of nominal locations"): the
    // share of nominal points with any configuration relabelled.
    j["switched_fraction"] = relabelled->switched_points_fraction();
    j["switched_points_fraction"] = relabelled->switched_points_fraction();
    j["n_switched_points"] = relabelled->n_switched_points;
    j["n_points"] = relabelled->n_points;
    j["switched_locations_fraction"] = relabelled->switched_locations_fraction();
    j["n_switched_locations"] = relabelled->n_switched;
    j["n_locations"] = relabelled->n_locations;
  }
  if (strategy == 3) {
    j["seed"] = p.seed ? nlohmann::json(*p.seed) : nlohmann::json(nullptr);
    std::vector<std::string> names;
    for (const std::size_t f : p.registration_fiducials) {
      names.push_back(location_name(model.fiducials[f]));
    }
    j["registration_fiducials"] = names;
    j["n_correction_fiducials"] = model.fiducials.size();
  }
}

nlohmann::json register_json(const RegisterResult& result) {
  const RegistrationModel& model = result.model;
  const RegistrationResult& reg = result.registration;
  const RigidBodyStatistics& rb = result.rigid_body;
  const Eigen::Matrix3d& r = model.T_robot_sensor.rotation;
  nlohmann::json j;
  j["n_fiducials"] = result.n_registered;
  j["rotation"] = {
      {r(0, 0), r(0, 1), r(0, 2)}, {r(1, 0), r(1, 1), r(1, 2)}, {r(2, 0), r(2, 1), r(2, 2)}};
  j["translation_mm"] = json_mm3(model.T_robot_sensor.translation_m);
  j["scale"] = model.T_robot_sensor.scale;
  j["fre_mm"] = units::m_to_mm(reg.fre_m);
  j["sigma_l_mm"] = units::m_to_mm(rb.sigma_l_m);
  j["mean_l_mm"] = units::m_to_mm(rb.mean_m);
  j["pairs"] = rb.pairs;
  if (result.sigma_l_sampling.sampled) {
    const SigmaLSampling& s = result.sigma_l_sampling;
    j["sigma_l_sampling"] = {
        {"pairs", s.pairs_sampled},
        {"pairs_total", s.pairs_total},
        {"seed", s.seed},
        {"confidence", s.confidence},
        {"interval_mm", {units::m_to_mm(s.sigma_l_low_m), units::m_to_mm(s.sigma_l_high_m)}}};
  }
  j["spread_mm"] = json_mm3(reg.spread_m);
  if (result.noise.sigma_opt_m) j["sigma_opt_mm"] = units::m_to_mm(*result.noise.sigma_opt_m);
  if (result.noise.sigma_noise_m) {
    j["sigma_noise_mm"] = units::m_to_mm(*result.noise.sigma_noise_m);
  }
  if (result.noise.rho) j["rho"] = *result.noise.rho;
  j["rejected"] = result.rejected;
  if (result.robust) j["robust"] = robust_json(*result.robust);
  if (result.cross_validation) {
    j["cross_validation"] = cross_validation_json(*result.cross_validation);
    j["interpolation"] = to_string(model.interpolation.method);
  }
  if (model.corrector && model.corrector->guard()) {
    j["guard"] = detail::guard_result_json(*model.corrector->guard());
  }
  // Only when the term entered: other cells print what they printed.
  if (model.corrector && model.corrector->lost_motion() && model.corrector->lost_motion()->applied)
    j["lost_motion"] = lost_motion_result_json(*model.corrector->lost_motion());
  if (model.orientation_corrector) j["orientation"] = orientation_field_json(*model.orientation_corrector);
  add_strategy_json(model, result.relabelled, j);
  return j;
}

nlohmann::json orientation_field_json(const OrientationCorrector& field) {
  constexpr double kMrad = 1e3;
  nlohmann::json j;
  j["method"] = to_string(field.method());
  j["applied"] = field.applied();
  j["status"] = field.applied() ? "ok" : to_string(StencilStatus::kNotBetterThanNone);
  j["describe"] = field.describe();
  j["uncorrected_rms_angle_mrad"] = kMrad * field.uncorrected_rms_rad();
  j["cv_rms_angle_mrad"] =
      field.cv_rms_rad() > 0.0 ? nlohmann::json(kMrad * field.cv_rms_rad()) : nlohmann::json(nullptr);
  nlohmann::json rows = nlohmann::json::array();
  for (const OrientationCvRow& row : field.cross_validation()) {
    nlohmann::json r;
    r["method"] = to_string(row.method);
    r["applicable"] = row.applicable;
    if (row.applicable) {
      r["rms_angle_mrad"] = kMrad * row.rms_rad;
      r["n_predicted"] = row.n_predicted;
    } else {
      r["note"] = row.note;
    }
    rows.push_back(std::move(r));
  }
  j["cross_validation"] = std::move(rows);
  return j;
}

nlohmann::json multidirectional_json(const MultidirectionalAccuracy& m) {
  nlohmann::json directions = nlohmann::json::array();
  for (const DirectionAccuracy& d : m.directions) {
    directions.push_back({{"approach", approach_text(d.approach_sign)},
                          {"n_targets", d.n_targets},
                          {"unc_rms_t_mm", units::m_to_mm(d.unc_rms_t_m)},
                          {"cor_rms_t_mm", units::m_to_mm(d.cor_rms_t_m)}});
  }
  return {{"n_points", m.n_points},
          {"directions", directions},
          {"unc_spread_max_mm", units::m_to_mm(m.unc_max_spread_m)},
          {"unc_spread_mean_mm", units::m_to_mm(m.unc_mean_spread_m)},
          {"cor_spread_max_mm", units::m_to_mm(m.cor_max_spread_m)},
          {"cor_spread_mean_mm", units::m_to_mm(m.cor_mean_spread_m)}};
}

nlohmann::json evaluate_json(const EvaluateResult& result) {
  const ImprovementSummary& s = result.summary;
  const TargetCorrection& c = result.correction;
  // The figures are over the corrected targets (n_corrected); none corrected: null.
  const auto corrected_mm = [&](double m) {
    return s.n_targets > 0 ? nlohmann::json(units::m_to_mm(m)) : nlohmann::json(nullptr);
  };
  nlohmann::json j;
  j["config"] = result.config ? nlohmann::json(*result.config) : nlohmann::json(nullptr);
  j["interpolation"] = to_string(c.method_used);
  j["layout"] = c.layout;
  if (c.method_used == InterpolationMethod::kOctuplet) {
    j["cube_mm"] = units::m_to_mm(result.interpolation.cube_edge_m);
  }
  j["n_targets"] = result.n_targets();
  j["n_corrected"] = s.n_targets;
  j["n_flagged"] = c.n_flagged;
  j["flagged_rms_t_mm"] = c.n_flagged > 0 ? nlohmann::json(units::m_to_mm(result.flagged_rms_t_m))
                                          : nlohmann::json(nullptr);
  j["unc_rms_t_mm"] = corrected_mm(s.unc_rms_t_m);
  j["cor_rms_t_mm"] = corrected_mm(s.cor_rms_t_m);
  j["gamma_percent"] = s.n_targets > 0 ? nlohmann::json(100.0 * s.gamma) : nlohmann::json(nullptr);
  j["n_bad"] = s.n_bad;
  j["bad_targets"] = result.bad_targets;
  j["unc_max_tre_mm"] = corrected_mm(s.unc_max_tre_m);
  j["cor_max_tre_mm"] = corrected_mm(s.cor_max_tre_m);
  add_predicted_sd_json(c, result.calibration, j);
  if (c.guard) j["guard"] = detail::guard_result_json(*c.guard);
  if (result.orientation) {  // rigid-body markers only: a sphere's JSON stays as it was
    const OrientationEvaluation& o = *result.orientation;
    nlohmann::json angle;
    angle["unc_rms_angle_mrad"] = 1e3 * o.unc_rms_rad;
    angle["cor_rms_angle_mrad"] = 1e3 * o.cor_rms_rad;
    angle["n_flagged"] = o.correction.n_flagged;
    if (o.calibration.n > 0) {
      angle["calibration"] = {{"n", o.calibration.n},
                              {"rms_angle_over_sd", o.calibration.rms_ratio},
                              {"within_2sd", o.calibration.within_2sigma}};
    }
    j["orientation"] = angle;
  }
  if (result.cross_validation)
    j["cross_validation"] = cross_validation_json(*result.cross_validation);
  if (result.multidirectional) j["multidirectional"] = multidirectional_json(*result.multidirectional);
  const int strategy = planning::strategy_number(result.strategy);
  j["strategy"] = strategy == 0 ? nlohmann::json(nullptr) : nlohmann::json(strategy);
  return j;
}

nlohmann::json evaluate_json(const EvaluateResult& result, const RegistrationModel& model) {
  nlohmann::json j = evaluate_json(result);
  add_strategy_json(model, result.relabelled, j);
  // Strategy 1 chosen at evaluation for a model built without one.
  if (result.strategy == planning::Strategy::kAsListed &&
      model.procedure2.strategy == planning::Strategy::kNone) {
    j["strategy"] = 1;
  }
  return j;
}

nlohmann::json correct_json(const CorrectResult& result) {
  const TargetCorrection& c = result.correction;
  nlohmann::json j;
  j["points"] = c.corrected_robot_m.cols();
  j["n_flagged"] = c.n_flagged;
  j["interpolation"] = to_string(c.method_used);
  j["layout"] = c.layout;
  add_predicted_sd_json(c, std::nullopt, j);
  if (c.guard) j["guard"] = detail::guard_result_json(*c.guard);
  if (result.cross_validation)
    j["cross_validation"] = cross_validation_json(*result.cross_validation);
  if (result.orientation) j["orientation"] = orientation_correction_json(*result.orientation);
  return j;
}

nlohmann::json orientation_correction_json(const OrientationCorrection& o) {
  constexpr double kMrad = 1e3;
  nlohmann::json j;
  j["interpolation"] = to_string(o.method_used);
  j["n_corrected"] = std::ssize(o.status) - o.n_flagged;
  j["n_flagged"] = o.n_flagged;
  nlohmann::json statuses = nlohmann::json::object();
  for (const StencilStatus s : o.status) {
    const char* name = to_string(s);
    statuses[name] = statuses.value(name, 0) + 1;
  }
  j["status_counts"] = std::move(statuses);
  const PredictedSdSummary sd = summarize_predicted_sd(o.predicted_sd_rad);
  if (sd.n > 0) {
    j["predicted_angle_sd_mrad"] = {{"median", kMrad * sd.median_m}, {"max", kMrad * sd.max_m}};
  }
  j["angle_sd_limit_mrad"] = kMrad * o.sd_limit_rad;
  std::size_t over = 0;
  for (std::size_t t = 0; t < o.status.size(); ++t) over += o.sd_over_limit(t) ? 1 : 0;
  j["n_angle_sd_over_limit"] = over;
  return j;
}

nlohmann::json marker_offset_register_json(const MarkerOffsetRegisterResult& result) {
  VRREG_THROW_UNLESS(result.ok(),
                     "marker offset: no result to report (" << result.estimate.message << ")");
  const MarkerOffsetResult& e = result.estimate;
  const RegisterResult& reg = *result.registered;
  const Eigen::Matrix3d& r = reg.model.T_robot_sensor.rotation;
  nlohmann::json j;
  j["n_fiducials"] = reg.n_registered;
  j["p_flange_marker_mm"] = json_mm3(e.p_flange_marker_m);
  j["p_std_mm"] = json_mm3(result.p_std_total_m);
  j["p_std_noise_mm"] = json_mm3(e.p_std_m);
  j["p_std_joint_offsets_mm"] = json_mm3(result.p_std_joint_offsets_m);
  j["rotation"] = {
      {r(0, 0), r(0, 1), r(0, 2)}, {r(1, 0), r(1, 1), r(1, 2)}, {r(2, 0), r(2, 1), r(2, 2)}};
  j["translation_mm"] = json_mm3(reg.model.T_robot_sensor.translation_m);
  j["translation_std_mm"] = json_mm3(e.translation_std_m);
  j["rotation_std_mrad"] = {1e3 * e.rotation_std_rad.x(), 1e3 * e.rotation_std_rad.y(),
                            1e3 * e.rotation_std_rad.z()};
  if (e.has_marker_orientation) {
    const Eigen::Quaterniond& q = e.q_flange_marker;
    j["q_flange_marker_xyzw"] = {q.x(), q.y(), q.z(), q.w()};
    j["marker_rotation_std_deg"] = {units::rad_to_deg(e.marker_rotation_std_rad.x()),
                                    units::rad_to_deg(e.marker_rotation_std_rad.y()),
                                    units::rad_to_deg(e.marker_rotation_std_rad.z())};
    j["sigma_orientation_deg"] = units::rad_to_deg(e.sigma_rad);
  }
  j["fre_mm"] = units::m_to_mm(e.fre_m);
  j["orientation_spread_rad"] = e.orientation_spread;
  j["condition_number"] = e.condition_number;
  j["iterations"] = e.iterations;
  j["sigma_l_mm"] = units::m_to_mm(reg.rigid_body.sigma_l_m);
  if (reg.noise.sigma_opt_m) j["sigma_opt_mm"] = units::m_to_mm(*reg.noise.sigma_opt_m);
  if (reg.noise.rho) j["rho"] = *reg.noise.rho;
  j["offset_only"] = result.offset_only;
  return j;
}

std::string brief_report(const RegisterResult& r) {
  std::string text = std::to_string(r.n_registered) + " fiducials, FRE " +
                     mm_text(r.registration.fre_m) + ", sigma_L " + mm_text(r.rigid_body.sigma_l_m);
  if (r.noise.sigma_noise_m) text += ", sigma_noise " + mm_text(*r.noise.sigma_noise_m);
  if (r.noise.rho) text += ", rho " + format_fixed(*r.noise.rho, 2);
  if (!r.rejected.empty()) text += ", " + std::to_string(r.rejected.size()) + " rejected";
  return text;
}

std::string brief_report(const EvaluateResult& r) {
  std::string text =
      std::to_string(r.n_targets()) + " targets, " + to_string(r.correction.method_used);
  if (r.summary.n_targets > 0) {
    text += ": RMS_T " + mm_text(r.summary.unc_rms_t_m) + " uncorrected, " +
            mm_text(r.summary.cor_rms_t_m) + " corrected, gamma " +
            format_fixed(100.0 * r.summary.gamma, 1) + "%, N_bad " +
            std::to_string(r.summary.n_bad);
  }
  text += ", n_flagged " + std::to_string(r.correction.n_flagged);
  if (r.correction.n_flagged > 0) text += " (RMS_T " + mm_text(r.flagged_rms_t_m) + " uncorrected)";
  return text;
}

std::string brief_report(const CorrectResult& r) {
  return std::to_string(r.correction.corrected_robot_m.cols()) + " points, " +
         to_string(r.correction.method_used) + ", n_flagged " +
         std::to_string(r.correction.n_flagged);
}

nlohmann::json lost_motion_result_json(const LostMotionTerm& term) {
  return detail::lost_motion_result_json(term);
}

}  // namespace vrreg::io
