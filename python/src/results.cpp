// SPDX-License-Identifier: Apache-2.0
// The results of register / evaluate / correct as small classes: scalars in metres, per-point
// arrays as read-only numpy views of the C++ result (no copy; the result stays alive with them).
#include <pybind11/stl.h>

#include <type_traits>

#include "arrays.hpp"
#include "bindings.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/result_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::python {
namespace {

// A property returning a view of one point set of the result.
template <typename Result, typename Get>
void points_property(py::class_<Result>& c, const char* name, Get get, const char* doc) {
  c.def_property_readonly(
      name, [get](py::object self) { return view_of(get(self.cast<const Result&>()), self); }, doc);
}

py::array status_codes(const TargetCorrection& c) {
  py::array_t<std::uint8_t> out(static_cast<py::ssize_t>(c.stencils.size()));
  for (std::size_t i = 0; i < c.stencils.size(); ++i) {
    out.mutable_at(static_cast<py::ssize_t>(i)) = static_cast<std::uint8_t>(c.stencils[i].status);
  }
  return out;
}

std::vector<std::string> status_names(const TargetCorrection& c) {
  std::vector<std::string> out;
  out.reserve(c.stencils.size());
  for (const Stencil& s : c.stencils) out.emplace_back(to_string(s.status));
  return out;
}

py::object strategy2_dict(const std::optional<planning::Strategy2Summary>& s) {
  if (!s) return py::none();
  py::dict d;
  d["n_points"] = s->n_points;
  d["n_locations"] = s->n_locations;
  d["n_switched_locations"] = s->n_switched;
  d["n_switched_points"] = s->n_switched_points;
  d["switched_points_fraction"] = s->switched_points_fraction();
  d["switched_locations_fraction"] = s->switched_locations_fraction();
  return d;
}

// The cross-validation table of interpolation 'auto' as a dict (metres), or None.
py::object cross_validation_dict(const std::optional<CrossValidation>& cv) {
  if (!cv) return py::none();
  py::list rows;
  for (const CrossValidationRow& row : cv->rows) {
    py::dict d;
    d["method"] = std::string(to_string(row.method));
    d["applicable"] = row.applicable;
    d["note"] = with_keywords(row.note);
    d["rms_ranked"] = row.rms_ranked_m;
    d["rms"] = row.rms_m;
    d["n_predicted"] = row.n_predicted;
    d["seconds"] = row.seconds;
    rows.append(d);
  }
  py::dict out;
  out["folds"] = cv->folds;
  out["seed"] = cv->seed;
  out["chosen"] = std::string(to_string(cv->chosen));
  out["rows"] = rows;
  return out;
}

// The correction guard's figures as a dict (metres), or None when the corrector was not guarded.
py::object guard_dict(const std::optional<CorrectionGuard>& g) {
  if (!g) return py::none();
  py::dict d;
  d["judged"] = g->judged;
  d["applied"] = g->applied;
  d["judged_by"] = std::string(to_string(g->judged_by));
  d["cv_rms"] = g->cv_rms_m;
  d["uncorrected_rms"] = g->uncorrected_rms_m;
  d["n_judged"] = g->n_judged;
  d["note"] = g->note;
  return d;
}

// The brief report of io (one place for the figures a result shows first), as Python's repr.
template <typename Result>
std::string repr_of(const char* type, const Result& r) {
  return std::string("<vrreg.") + type + " " + io::brief_report(r) + ">";
}

// A figure of the corrected targets, or None when no target was corrected.
py::object of_corrected(const EvaluateResult& r, double value) {
  return r.summary.n_targets > 0 ? py::object(py::float_(value)) : py::object(py::none());
}

// (N, 3, 3) rotation matrices, robot frame.
py::array_t<double> rotations(const std::vector<Eigen::Matrix3d>& r) {
  py::array_t<double> out({static_cast<py::ssize_t>(r.size()), py::ssize_t{3}, py::ssize_t{3}});
  auto a = out.mutable_unchecked<3>();
  for (std::size_t k = 0; k < r.size(); ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a(static_cast<py::ssize_t>(k), i, j) = r[k](i, j);
  return out;
}

// A vector as a 1-D array, or None when empty.
py::object array_or_none(const Eigen::VectorXd& v) {
  if (v.size() == 0) return py::none();
  return py::array_t<double>(v.size(), v.data());
}

// The corrected orientations (rigid-body markers), or None (docs/orientation.md).
py::object orientation_dict(const std::optional<OrientationCorrection>& o) {
  if (!o) return py::none();
  py::dict d;
  d["R_robot_marker_corrected"] = rotations(o->corrected_R_robot_marker);
  d["R_robot_marker_uncorrected"] = rotations(o->uncorrected_R_robot_marker);
  py::array_t<double> q(
      {static_cast<py::ssize_t>(o->corrected_R_robot_marker.size()), py::ssize_t{4}});
  auto qa = q.mutable_unchecked<2>();
  for (std::size_t k = 0; k < o->corrected_R_robot_marker.size(); ++k) {
    const Eigen::Quaterniond qk(o->corrected_R_robot_marker[k]);
    for (int i = 0; i < 4; ++i) qa(static_cast<py::ssize_t>(k), i) = qk.coeffs()(i);
  }
  d["q_robot_marker_corrected"] = q;
  Eigen::MatrixXd rotation = o->corrections_robot_rad.transpose();
  d["rotation_robot"] =
      py::array_t<double>({rotation.rows(), rotation.cols()},
                          {sizeof(double), sizeof(double) * rotation.rows()}, rotation.data());
  d["predicted_angle_sd"] = array_or_none(o->predicted_sd_rad);
  d["n_flagged"] = o->n_flagged;
  return d;
}

// What evaluate and correct share: the interpolation used and the corrected points.
template <typename Result>
void bind_correction_members(py::class_<Result>& c) {
  c.def_property_readonly(
       "method", [](const Result& r) { return std::string(to_string(r.correction.method_used)); },
       "interpolation used: 'grid', 'scattered', 'octuplet' (Eq. 7) or a field model "
       "('trilinear', 'kriging', 'rbf', 'joint')")
      .def_property_readonly(
          "layout", [](const Result& r) { return r.correction.layout; },
          "what the interpolation used, in words")
      .def_property_readonly(
          "cube_edge", [](const Result& r) { return r.interpolation.cube_edge_m; },
          "octuplet cube edge [m] (0 when not set)")
      .def_property_readonly(
          "n_flagged", [](const Result& r) { return r.correction.n_flagged; },
          "points left uncorrected (status != OK)")
      .def_property_readonly("names", [](const Result& r) { return r.names; })
      .def_property_readonly("configs", [](const Result& r) { return r.configs; })
      .def_property_readonly(
          "status", [](const Result& r) { return status_codes(r.correction); },
          "(N,) uint8 StencilStatus per point (0 = OK)")
      .def_property_readonly(
          "status_names", [](const Result& r) { return status_names(r.correction); },
          "status per point as text ('ok', 'outside grid', ...)")
      .def_property_readonly(
          "predicted_sd",
          [](const Result& r) -> py::object {
            if (r.correction.predicted_sd_m.size() == 0) return py::none();
            return py::array_t<double>(r.correction.predicted_sd_m.size(),
                                       r.correction.predicted_sd_m.data());
          },
          "field models: (N,) predicted standard uncertainty of each corrected point's 3D error "
          "[m] (NaN where not corrected); None for the paper's stencils")
      .def_property_readonly(
          "cross_validation",
          [](const Result& r) { return cross_validation_dict(r.cross_validation); },
          "interpolation 'auto': the K-fold cross-validation table [m] and its choice (dict)")
      .def_property_readonly(
          "guard", [](const Result& r) { return guard_dict(r.correction.guard); },
          "whether the correction was applied: its cross-validated RMS against the uncorrected "
          "one [m] (judged, applied, judged_by, cv_rms, uncorrected_rms, n_judged, note); not "
          "applied: every point uncorrected, status NOT_BETTER_THAN_NONE. None: not guarded")
      .def_property_readonly(
          "orientation",
          [](const Result& r) {
            if constexpr (std::is_same_v<Result, EvaluateResult>) {
              return orientation_dict(r.orientation ? std::optional(r.orientation->correction)
                                                    : std::nullopt);
            } else {
              return orientation_dict(r.orientation);
            }
          },
          "rigid-body markers (a file with sensor_q and robot_q columns): the corrected "
          "orientations, robot frame: R_robot_marker_corrected (N, 3, 3), what to command, "
          "R_robot_marker_uncorrected (N, 3, 3), q_robot_marker_corrected (N, 4) x y z w, "
          "rotation_robot (N, 3) the rotation applied [rad], predicted_angle_sd (N,) [rad] or "
          "None, n_flagged (dict); None without orientations");
  points_property(
      c, "corrected",
      [](const Result& r) -> const Points3& { return r.correction.corrected_robot_m; },
      "(N, 3) RRBC-corrected positions, robot frame [m]: what to command (Eq. 8)");
  points_property(
      c, "uncorrected",
      [](const Result& r) -> const Points3& { return r.correction.uncorrected_robot_m; },
      "(N, 3) R X + tau, robot frame [m]");
  points_property(
      c, "corrections",
      [](const Result& r) -> const Points3& { return r.correction.corrections_sensor_m; },
      "(N, 3) interpolated corrections epsilon(T_X) (Eq. 7), sensor frame [m]");
}

}  // namespace

void bind_results(py::module_& m) {
  py::enum_<StencilStatus>(m, "StencilStatus", "Why a point has no interpolated correction.")
      .value("OK", StencilStatus::kOk)
      .value("OUTSIDE_GRID", StencilStatus::kOutsideGrid)
      .value("OUTSIDE_HULL", StencilStatus::kOutsideHull)
      .value("MISSING_CORNER", StencilStatus::kMissingCorner)
      .value("OUTSIDE_SUPPORT", StencilStatus::kOutsideSupport)
      .value("EXTRAPOLATED", StencilStatus::kExtrapolated)
      .value("TOO_FEW_FIDUCIALS", StencilStatus::kTooFewFiducials)
      .value("NOT_BETTER_THAN_NONE", StencilStatus::kNotBetterThanNone)
      .value("FLAT_LAYOUT", StencilStatus::kFlatLayout);

  py::class_<RegisterResult> reg(m, "RegisterResult", "What register found; lengths in metres.");
  reg.def_property_readonly(
         "model", [](const RegisterResult& r) -> const RegistrationModel& { return r.model; },
         py::return_value_policy::reference_internal, "the vrreg.Model built")
      .def_property_readonly(
          "fre", [](const RegisterResult& r) { return r.registration.fre_m; },
          "FRE: RMS fit residual (Eq. 2) [m] (not target accuracy: evaluate)")
      .def_property_readonly(
          "sigma_l", [](const RegisterResult& r) { return r.rigid_body.sigma_l_m; },
          "sigma_L: std of L_ij over all fiducial pairs (Eq. 1) [m]")
      .def_property_readonly(
          "mean_l", [](const RegisterResult& r) { return r.rigid_body.mean_m; },
          "mean of L_ij (Eq. 1) [m]")
      .def_property_readonly("pairs", [](const RegisterResult& r) { return r.rigid_body.pairs; })
      .def_property_readonly(
          "sigma_opt", [](const RegisterResult& r) { return optional_value(r.noise.sigma_opt_m); },
          "sensor noise per axis from repeat readings [m], or None")
      .def_property_readonly(
          "sigma_rep", [](const RegisterResult& r) { return optional_value(r.noise.sigma_rep_m); },
          "robot repeatability as given [m], or None")
      .def_property_readonly(
          "sigma_noise",
          [](const RegisterResult& r) { return optional_value(r.noise.sigma_noise_m); },
          "sqrt(sigma_opt^2 + sigma_rep^2) (Eq. 9) [m], or None")
      .def_property_readonly(
          "rho", [](const RegisterResult& r) { return optional_value(r.noise.rho); },
          "sigma_L / sigma_noise: RRBC helps when > 2.5; or None")
      .def_property_readonly("rho_is_upper_bound",
                             [](const RegisterResult& r) { return r.noise.rho_is_upper_bound(); })
      .def_property_readonly(
          "rejected", [](const RegisterResult& r) { return r.rejected; },
          "robust: names of the rejected fiducials")
      .def_property_readonly(
          "outliers",
          [](const RegisterResult& r) {
            py::list out;
            if (!r.robust) return out;
            for (const RejectedFiducial& f : r.robust->rejected) {
              py::dict d;
              d["point"] = f.point;
              d["config"] = f.config ? py::object(py::int_(*f.config)) : py::object(py::none());
              d["deviation"] = f.deviation_m;
              d["sigmas"] = f.sigmas;
              d["filled"] = f.filled;
              out.append(d);
            }
            return out;
          },
          "robust: per rejected fiducial a dict: point, config, deviation [m] from its "
          "neighbours' prediction, sigmas, filled (kept with its neighbours' correction)")
      .def_property_readonly("n_registered", [](const RegisterResult& r) { return r.n_registered; })
      .def_property_readonly(
          "rotation",
          [](const RegisterResult& r) { return matrix_copy(r.model.T_robot_sensor.rotation); },
          "R (3, 3), sensor -> robot (Eq. 2)")
      .def_property_readonly(
          "translation",
          [](const RegisterResult& r) { return vector_copy(r.model.T_robot_sensor.translation_m); },
          "tau (3,), robot frame [m]")
      .def_property_readonly("scale",
                             [](const RegisterResult& r) { return r.model.T_robot_sensor.scale; })
      .def_property_readonly(
          "spread", [](const RegisterResult& r) { return vector_copy(r.registration.spread_m); },
          "RMS spread along the principal axes [m]")
      .def_property_readonly(
          "residuals",
          [](py::object self) {
            return view_of(self.cast<const RegisterResult&>().registration.residuals_m, self);
          },
          "(N,) ||R X + tau - Y|| per registered fiducial [m]")
      .def_property_readonly(
          "relabelled", [](const RegisterResult& r) { return strategy2_dict(r.relabelled); },
          "strategy 2: what was relabelled (dict), else None")
      .def_property_readonly(
          "cross_validation",
          [](const RegisterResult& r) { return cross_validation_dict(r.cross_validation); },
          "interpolation 'auto': the K-fold cross-validation table [m] and its choice (dict)")
      .def(
          "to_json",
          [](const RegisterResult& r) { return with_keywords(io::register_json(r).dump(2)); },
          "the JSON `vrreg register --json` prints for this result (lengths in mm), as a string")
      .def("__repr__", [](const RegisterResult& r) { return repr_of("RegisterResult", r); });

  py::class_<EvaluateResult> ev(m, "EvaluateResult",
                                "A model's accuracy on targets; lengths in metres.");
  bind_correction_members(ev);
  ev.def_property_readonly("n_targets", &EvaluateResult::n_targets,
                           "every target evaluated, corrected or not")
      .def_property_readonly(
          "n_corrected", [](const EvaluateResult& r) { return r.summary.n_targets; },
          "the targets corrected: unc_rms_t, cor_rms_t, gamma and n_bad are over these only")
      .def_property_readonly(
          "flagged_rms_t",
          [](const EvaluateResult& r) -> py::object {
            if (r.correction.n_flagged == 0) return py::none();
            return py::float_(r.flagged_rms_t_m);
          },
          "RMS_T of the n_flagged targets left uncorrected, as registered [m]; None if none")
      .def_property_readonly(
          "multidirectional",
          [](const EvaluateResult& r) -> py::object {
            if (!r.multidirectional) return py::none();
            const MultidirectionalAccuracy& accuracy = *r.multidirectional;
            py::list directions;
            for (const DirectionAccuracy& d : accuracy.directions) {
              py::dict one;
              one["approach"] = approach_text(d.approach_sign);
              one["n_targets"] = d.n_targets;
              one["unc_rms_t"] = d.unc_rms_t_m;
              one["cor_rms_t"] = d.cor_rms_t_m;
              directions.append(one);
            }
            py::dict out;
            out["n_points"] = accuracy.n_points;
            out["directions"] = directions;
            out["unc_spread_max"] = accuracy.unc_max_spread_m;
            out["unc_spread_mean"] = accuracy.unc_mean_spread_m;
            out["cor_spread_max"] = accuracy.cor_max_spread_m;
            out["cor_spread_mean"] = accuracy.cor_mean_spread_m;
            return out;
          },
          "ISO 9283's multi-directional accuracy over the corrected targets [m] (n_points, "
          "directions: approach, n_targets, unc_rms_t, cor_rms_t; unc/cor_spread_max/mean), "
          "as `vrreg evaluate` prints it; None unless some target point was visited from two "
          "approach directions")
      .def_property_readonly(
          "unc_rms_t",
          [](const EvaluateResult& r) { return of_corrected(r, r.summary.unc_rms_t_m); },
          "RMS_T uncorrected (Eq. 4) of the corrected targets [m]; None if none was corrected")
      .def_property_readonly(
          "cor_rms_t",
          [](const EvaluateResult& r) { return of_corrected(r, r.summary.cor_rms_t_m); },
          "RMS_T RRBC-corrected (Eq. 4, 8) [m]; None if no target was corrected")
      .def_property_readonly(
          "gamma", [](const EvaluateResult& r) { return of_corrected(r, r.summary.gamma); },
          "(unc - cor) / unc over the corrected targets, a fraction (x100 for the paper's %); "
          "None if none was corrected")
      .def_property_readonly(
          "n_bad", [](const EvaluateResult& r) { return r.summary.n_bad; },
          "N_bad: corrected targets whose TRE RRBC made worse")
      .def_property_readonly("bad_targets", [](const EvaluateResult& r) { return r.bad_targets; })
      .def_property_readonly(
          "strategy", [](const EvaluateResult& r) { return planning::strategy_number(r.strategy); },
          "Procedure 2 strategy used (0: none)")
      .def_property_readonly("config",
                             [](const EvaluateResult& r) { return optional_value(r.config); })
      .def_property_readonly("relabelled",
                             [](const EvaluateResult& r) { return strategy2_dict(r.relabelled); })
      .def_property_readonly(
          "calibration",
          [](const EvaluateResult& r) -> py::object {
            if (r.calibration.n == 0) return py::none();
            py::dict d;
            d["n"] = r.calibration.n;
            d["rms_tre_over_sd"] = r.calibration.rms_ratio;
            d["within_2sd"] = r.calibration.within_2sigma;
            return d;
          },
          "field models: RMS of TRE / predicted sd (1 = calibrated) and the fraction within "
          "2 sd (dict), else None")
      .def_property_readonly(
          "angle_errors",
          [](const EvaluateResult& r) -> py::object {
            if (!r.orientation) return py::none();
            const OrientationEvaluation& o = *r.orientation;
            py::dict d;
            d["unc"] = py::array_t<double>(o.unc_error_rad.size(), o.unc_error_rad.data());
            d["cor"] = py::array_t<double>(o.cor_error_rad.size(), o.cor_error_rad.data());
            d["unc_rms"] = o.unc_rms_rad;
            d["cor_rms"] = o.cor_rms_rad;
            d["rms_angle_over_sd"] =
                o.calibration.n > 0 ? py::object(py::float_(o.calibration.rms_ratio)) : py::none();
            return d;
          },
          "rigid-body markers: each target's angle between the commanded and the (un)corrected "
          "orientation [rad], unc/cor (N,), their RMS over the corrected targets, and the RMS of "
          "angle / predicted sd (dict); None without orientations")
      .def(
          "to_json",
          [](const EvaluateResult& r) { return with_keywords(io::evaluate_json(r).dump(2)); },
          "the JSON `vrreg evaluate --json` prints for this result (lengths in mm), as a string")
      .def("__repr__", [](const EvaluateResult& r) { return repr_of("EvaluateResult", r); });
  ev.def_property_readonly(
        "unc_tre",
        [](py::object self) { return view_of(self.cast<const EvaluateResult&>().unc_tre_m, self); },
        "(N,) TRE(T_X) per target (Eq. 3) [m]")
      .def_property_readonly(
          "cor_tre",
          [](py::object self) {
            return view_of(self.cast<const EvaluateResult&>().cor_tre_m, self);
          },
          "(N,) TRE of the corrected targets [m] (flagged: uncorrected)")
      .def_property_readonly(
          "delta_tre",
          [](py::object self) {
            return view_of(self.cast<const EvaluateResult&>().summary.delta_tre_m, self);
          },
          "TRE(cor) - TRE(unc) where it improved (< 0), Fig. 11 [m]");
  points_property(
      ev, "targets_robot",
      [](const EvaluateResult& r) -> const Points3& { return r.targets_robot_m; },
      "(N, 3) nominal target positions, robot frame [m]");

  py::class_<CorrectResult> cor(m, "CorrectResult",
                                "Corrected points, in the order given; metres.");
  bind_correction_members(cor);
  cor.def(
         "to_json",
         [](const CorrectResult& r) { return with_keywords(io::correct_json(r).dump(2)); },
         "the JSON `vrreg correct --json` prints for this result (lengths in mm), as a string")
      .def("__repr__", [](const CorrectResult& r) { return repr_of("CorrectResult", r); });
}

}  // namespace vrreg::python
