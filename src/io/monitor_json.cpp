// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/monitor_json.hpp"

#include "vrreg/core/units.hpp"
#include "vrreg/io/result_json.hpp"

namespace vrreg::io {
namespace {

nlohmann::json optional_config(const std::optional<int>& config) {
  return config ? nlohmann::json(*config) : nlohmann::json(nullptr);
}

// (omega [mrad], t [mm]) from (rad, m): both scale by 1e3, the covariance by 1e6.
nlohmann::json covariance_json(const Eigen::Matrix<double, 6, 6>& covariance) {
  nlohmann::json cov = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int k = 0; k < 6; ++k) row.push_back(1e6 * covariance(i, k));
    cov.push_back(std::move(row));
  }
  return cov;
}

nlohmann::json rigid_json(const RigidChange& c) {
  const Eigen::Vector3d mrad = 1e3 * c.rotation_rad;
  return {{"rotation_mrad", {mrad.x(), mrad.y(), mrad.z()}},
          {"rotation_axes_seen", c.rotation_rank},
          {"translation_mm", json_mm3(c.translation_m)},
          {"covariance_mrad_mm", covariance_json(c.covariance)},
          {"monitors_centroid_mm", json_mm3(c.centroid_m)},
          {"translation_at_monitors_mm", json_mm3(c.translation_at_centroid_m)},
          {"covariance_at_monitors_mrad_mm", covariance_json(c.covariance_at_centroid)},
          {"displacement_rms_mm", units::m_to_mm(c.displacement_rms_m)}};
}

nlohmann::json noise_json(const VisitNoiseComparison& n) {
  return {{"tested", n.tested},   {"noisier", n.noisier},   {"variance_ratio", n.ratio},
          {"p_value", n.p_value}, {"then_dof", n.dof_then}, {"today_dof", n.dof_today}};
}

nlohmann::json onset_json(const CheckResult& r) {
  const ChangeOnsetTest& o = r.onset;
  nlohmann::json j = {
      {"kind", to_string(o.onset)}, {"earlier_checks", o.earlier_checks}, {"times", r.onset_times}};
  if (o.onset != ChangeOnset::kUnknown) {
    j["statistic"] = o.statistic;
    j["bound"] = o.bound;
    j["fractions"] = o.fractions;
    j["step_after"] = o.step_after;
  }
  return j;
}

}  // namespace

nlohmann::json check_json(const CheckResult& r) {
  const MonitorCheck& s = r.statistics;
  nlohmann::json j;
  j["verdict"] = to_string(s.verdict);
  j["message"] = s.message;
  j["false_alarm_rate"] = r.false_alarm_rate;
  j["n_monitors"] = r.points.size();
  j["model_monitors"] = r.model_monitors;
  j["model_id"] = r.model_id;
  j["visit_sd_mm"] = units::m_to_mm(r.visit_sd_m);
  j["today_visit_sd_mm"] = units::m_to_mm(r.today_visit_sd_m);
  j["visit_sd_dof"] = r.variance_dof;
  j["noise"] = noise_json(r.noise);
  j["change_rms_mm"] = units::m_to_mm(s.change_rms_m);
  j["chi2"] = s.chi2;
  j["dof"] = s.dof;
  if (s.rigid_threshold > 0.0) {
    j["rigid_chi2"] = s.rigid_chi2;
    j["rigid_dof"] = s.rigid_dof;
    j["rigid_bound"] = s.rigid_threshold;
    j["residual_chi2"] = s.rigid_residual_chi2;
    j["residual_dof"] = s.residual_dof;
    j["residual_bound"] = s.residual_threshold;
  } else {
    j["bound"] = s.threshold;
  }
  nlohmann::json points = nlohmann::json::array();
  for (const MonitorPointCheck& p : r.points) {
    points.push_back({{"point", p.point},
                      {"config", optional_config(p.config)},
                      {"baseline_visits", p.baseline_visits},
                      {"today_visits", p.today_visits},
                      {"moved_mm", json_mm3(p.difference_m)},
                      {"sd_mm", units::m_to_mm(p.difference_sd_m)},
                      {"today_mean_sd_mm", units::m_to_mm(p.today_mean_sd_m)}});
  }
  j["points"] = std::move(points);
  if (s.rigid) j["sensor_moved"] = rigid_json(*s.rigid);
  if (s.outlier) j["outlier"] = r.points[static_cast<std::size_t>(*s.outlier)].point;
  j["onset"] = onset_json(r);
  j["blind_spots"] = s.blind_spots;
  j["remeasure"] = r.remeasure;
  j["source"] = r.source;
  return j;
}

nlohmann::json update_json(const UpdateResult& r) {
  nlohmann::json j;
  const ModelUpdate& last = r.model.lineage.back();
  j["change"] = last.change;
  j["points"] = r.points;
  j["n_monitors"] = r.n_monitors;
  j["n_fiducials"] = r.n_fiducials;
  j["fit_rms_mm"] = units::m_to_mm(r.fit_rms_m);
  if (last.change == "bump") {
    nlohmann::json rotation = nlohmann::json::array();
    for (int i = 0; i < 3; ++i) {
      rotation.push_back({r.T_registered_sensor.rotation(i, 0),
                          r.T_registered_sensor.rotation(i, 1),
                          r.T_registered_sensor.rotation(i, 2)});
    }
    j["T_registered_sensor"] = {{"rotation", std::move(rotation)},
                                {"translation_mm", json_mm3(r.T_registered_sensor.translation_m)}};
  } else {
    nlohmann::json a = nlohmann::json::array();
    for (int i = 0; i < 3; ++i) a.push_back({r.drift(i, 0), r.drift(i, 1), r.drift(i, 2)});
    j["drift"] = {{"per_metre", std::move(a)}, {"offset_mm", json_mm3(r.drift.col(3))}};
  }
  j["today_check"] =
      r.today_check ? nlohmann::json({{"verdict", to_string(r.today_check->statistics.verdict)},
                                      {"message", r.today_check->statistics.message}})
                    : nlohmann::json(nullptr);
  nlohmann::json lineage = nlohmann::json::array();
  for (const ModelUpdate& u : r.model.lineage) {
    lineage.push_back({{"change", u.change},
                       {"parent", u.parent},
                       {"points_source", u.points_source},
                       {"n_points", u.points.size()},
                       {"time", u.time},
                       {"fit_rms_mm", units::m_to_mm(u.fit_rms_m)}});
  }
  j["lineage"] = std::move(lineage);
  return j;
}

}  // namespace vrreg::io
