// SPDX-License-Identifier: Apache-2.0
#include "lost_motion_stage.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "lost_motion.hpp"
#include "method_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/correction/correction_guard.hpp"
#include "vrreg/correction/cross_validation.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/metrics/distributions.hpp"

namespace vrreg {

const char* to_string(LostMotionMode mode) {
  switch (mode) {
    case LostMotionMode::kAuto:
      return "auto";
    case LostMotionMode::kOff:
      return "off";
    case LostMotionMode::kOn:
      return "on";
  }
  return "auto";
}

LostMotionMode parse_lost_motion_mode(const std::string& text) {
  if (text == "auto") return LostMotionMode::kAuto;
  if (text == "off") return LostMotionMode::kOff;
  if (text == "on") return LostMotionMode::kOn;
  VRREG_THROW_UNLESS(false, "lost motion must be auto, off or on, got '" << text << "'");
  return LostMotionMode::kAuto;
}

namespace detail {
namespace {

// The term enters (auto) when its cross-validated RMS is at most this share of the method's
// alone: a 5 % gain is well beyond what 6 extra parameters fitted on hundreds of fiducials win
// by chance (on the UR5 cell without lost motion the two differ by < 0.5 %), and below what a
// backlash of a few tenths of an arc-minute gives (~15 % on the UR5 half-A1 cell).
constexpr double kEnterRatio = 0.95;

// With the joint model as the judge (the plays backfitted beside it), the term also enters on
// any cross-validated gain when the plays are jointly significant at this level (Wald). Fiducials
// visited along a raster share their approach directions with their neighbours, so the plays
// show less at held-out fiducials than at targets approached from elsewhere: on the tilted-tool
// UR5 and KUKA sweep cells with lost motion the raster's gain was 1.2-2.4 % (plays significant,
// Wald 26-77 on 5-6 joints) where the term took the targets from 1.19x the noise floor to
// 1.11-1.15x. Without lost motion the joint model's plays gave Wald 0.6-10.5 on 4-6 joints
// (p > 0.05): a chance gain there does not pass. The quadratic trend's plays are no test: its
// misfit inflates them (Wald 30-500 on cells without lost motion).
constexpr double kSignificanceTail = 1e-3;

constexpr double kArcminRad = M_PI / (180.0 * 60.0);
// The largest play auto believes: ISO 9283 figures and gear makers' data put industrial joints'
// lost motion at 0.5-3 arc-min new, a few more worn; 10 leaves room for a worn cycloidal gear.
constexpr double kMaxPlausiblePlayRad = 10.0 * kArcminRad;

// A play is a gap: never negative, and a few arc-minutes even in a worn gear. Plays outside that
// are the sign pattern standing in for something else (the arm's other errors on joints whose
// directions move together, IK switching branches). The first such joint, as ": but joint j's
// play ... is no lost motion"; empty when every play is plausible.
std::string implausible_play(const LostMotionTerm& term) {
  for (Eigen::Index j = 0; j < term.play_rad.size(); ++j) {
    const double sd_rad = std::sqrt(std::max(term.covariance_rad2(j, j), 0.0));
    const double play_rad = term.play_rad(j);
    if (play_rad < -3.0 * sd_rad || play_rad - 3.0 * sd_rad > kMaxPlausiblePlayRad) {
      char line[160];
      std::snprintf(line, sizeof line, ": but joint %ld's play %.2f arcmin (sd %.2f) is no lost motion",
                    static_cast<long>(j + 1), play_rad / kArcminRad, sd_rad / kArcminRad);
      return line;
    }
  }
  return {};
}

struct Wald {
  double statistic = 0.0;
  int dof = 0;  ///< the plays the data determine (the covariance's rank)
};

// beta^T Cov^+ beta over the directions the covariance resolves: a joint whose column vanishes
// at every fiducial (a wrist joint turning about the marker) has no play to test.
Wald wald_test(const LostMotionTerm& term) {
  Wald out;
  if (term.play_rad.size() == 0) return out;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(term.covariance_rad2);
  const double largest = eigen.eigenvalues().maxCoeff();
  for (Eigen::Index i = 0; i < eigen.eigenvalues().size(); ++i) {
    const double variance = eigen.eigenvalues()(i);
    if (!(variance > 1e-12 * largest)) continue;
    const double projection = eigen.eigenvectors().col(i).dot(term.play_rad);
    out.statistic += projection * projection / variance;
    ++out.dof;
  }
  return out;
}

// Robot-frame deviations (reached minus commanded) of the fiducials' corrections: the registered
// position R X + tau minus the command is -s R epsilon (Eq. 6).
Points3 deviation_robot_m(const CorrectorData& data) {
  const SimilarityTransform& T = data.T_robot_sensor;
  return -T.scale * (T.rotation * data.corrections_sensor_m);
}

}  // namespace

std::string lost_motion_unavailable(const CorrectorData& data) {
  if (!data.has_joints()) return "the fiducials have no joints";
  if (!data.robot) return "no robot is given for the fiducials' joints";
  if (!data.has_approach()) {
    return "the fiducials' approach directions are unknown (give from_q columns or rows in "
           "visiting order)";
  }
  for (Eigen::Index j = 0; j < data.approach_sign.rows(); ++j) {
    if (data.approach_sign.row(j).maxCoeff() > 0.0 && data.approach_sign.row(j).minCoeff() < 0.0)
      return {};
  }
  return "no joint was approached from both directions";
}

Points3 lost_motion_correction_sensor_m(const kinematics::SerialChain& chain,
                                        const SimilarityTransform& T_robot_sensor,
                                        const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                                        const Eigen::Ref<const Eigen::MatrixXd>& approach_sign,
                                        const Eigen::Ref<const Eigen::VectorXd>& play_rad) {
  const Points3 deviation_m = lost_motion_deviation_m(chain, joints_rad, approach_sign, play_rad);
  return -(T_robot_sensor.rotation.transpose() * deviation_m) / T_robot_sensor.scale;
}

CorrectorData without_lost_motion(const CorrectorData& data,
                                  const Eigen::Ref<const Eigen::VectorXd>& play_rad) {
  CorrectorData out = data;
  out.corrections_sensor_m -= lost_motion_correction_sensor_m(
      *data.robot, data.T_robot_sensor, data.joints_rad, data.approach_sign, play_rad);
  return out;
}

namespace {

// Plays fitted beside a parametric model of the arm instead of a polynomial trend (backfitting):
// the joint model, fitted on the corrections without the term, predicts the fiducials; the plays
// are fitted on what it leaves (with an affine trend), the term taken out and the model refitted,
// twice. A joint model cannot absorb a sign that flips along the path, so the plays come out
// unbiased where a quadratic trend leaves a transmission error or gravity sag in them (mixed UR5
// cells: the quadratic's plays left 1.22x the floor, these 1.0x).
LostMotionFit backfit_plays(const kinematics::SerialChain& chain, const CorrectorData& data,
                            const FittedMethod& plain, const MethodSettings& settings,
                            FitOutcome* staged_out) {
  CorrectorData left = data;
  left.corrections_sensor_m -= predict_held_out(plain, data).corrections_sensor_m;
  LostMotionFit fit = fit_lost_motion(chain, data.joints_rad, data.approach_sign,
                                      data.fiducials_robot_m, deviation_robot_m(left), 1);
  for (int pass = 0; pass < 2; ++pass) {
    const CorrectorData staged = without_lost_motion(data, fit.beta_rad);
    FitOutcome refit = plain.refit(staged, settings);
    if (!refit.fitted) break;
    left = data;
    left.corrections_sensor_m -= predict_held_out(*refit.fitted, data).corrections_sensor_m;
    fit = fit_lost_motion(chain, data.joints_rad, data.approach_sign, data.fiducials_robot_m,
                          deviation_robot_m(left), 1);
    if (staged_out != nullptr) *staged_out = std::move(refit);
  }
  return fit;
}

// The joint model judges the term for `auto` and `joint` on cells of up to this many fiducials
// (one fit of it and a solve per fold; on larger cells the cheap judge keeps register fast).
constexpr Eigen::Index kJointJudgeMaxFiducials = 3000;

}  // namespace

LostMotionTerm fit_lost_motion_term(const CorrectorData& data, LostMotionMode mode,
                                    const MethodSettings& settings, int folds, std::uint64_t seed,
                                    InterpolationMethod requested) {
  const kinematics::SerialChain& chain = *data.robot;
  LostMotionFit all = fit_lost_motion(chain, data.joints_rad, data.approach_sign,
                                      data.fiducials_robot_m, deviation_robot_m(data));
  LostMotionTerm term;
  // The judge: the joint model for `auto` and `joint` (the arm's own errors, which the quadratic
  // trend cannot follow, stay out of the plays), else the cheapest field model that fits
  // (trilinear a lattice fill per fold, RBF a dense solve where the layout is no lattice): what
  // the term adds is a sign flip between neighbouring fiducials that no smooth field fits.
  std::vector<InterpolationMethod> judges = {InterpolationMethod::kTrilinear,
                                             InterpolationMethod::kRbf};
  if ((requested == InterpolationMethod::kAuto || requested == InterpolationMethod::kJoint) &&
      data.size() <= kJointJudgeMaxFiducials)
    judges.insert(judges.begin(), InterpolationMethod::kJoint);
  FitOutcome plain;
  std::string not_applicable;
  for (const InterpolationMethod m : judges) {
    plain = fit_method(m, data, settings);
    if (plain.fitted) {
      term.judged_by = m;
      break;
    }
    not_applicable += std::string(not_applicable.empty() ? "" : "; ") + plain.not_applicable;
  }
  const bool backfit = plain.fitted && term.judged_by == InterpolationMethod::kJoint;
  FitOutcome staged;
  if (backfit) all = backfit_plays(chain, data, *plain.fitted, settings, &staged);
  term.play_rad = all.beta_rad;
  term.covariance_rad2 = all.covariance_rad2;
  if (mode == LostMotionMode::kOn) {
    term.applied = true;
    term.reason = "asked for (--lost-motion on)" + implausible_play(term);
    return term;
  }
  // The method alone and with the term, each refitted on the same folds; the term's plays are
  // refitted on each fold's training fiducials, so the held-out ones never inform them.
  if (!plain.fitted) {
    term.reason = "not cross-validated (" + not_applicable + ")";
    return term;
  }
  const InterpolationMethod judge = term.judged_by;
  if (!staged.fitted) staged = fit_method(judge, without_lost_motion(data, term.play_rad), settings);
  if (!staged.fitted) {
    term.reason = "not cross-validated (" + staged.not_applicable + ")";
    return term;
  }
  const std::vector<Eigen::Index> units = fold_units(data.fiducials_robot_m);
  const std::vector<int> fold_of = assign_folds(units, folds, seed);
  double sum_with_m2 = 0.0;
  double sum_without_m2 = 0.0;
  for (int f = 0; f < folds; ++f) {
    std::vector<Eigen::Index> train;
    std::vector<Eigen::Index> test;
    for (Eigen::Index j = 0; j < data.size(); ++j)
      (fold_of[static_cast<std::size_t>(j)] == f ? test : train).push_back(j);
    if (test.empty()) continue;
    const CorrectorData trained = data.subset(train);
    const CorrectorData held_out = data.subset(test);
    const FitOutcome without = plain.fitted->refit(trained, settings);
    if (!without.fitted) continue;
    LostMotionFit fold_fit;
    try {
      if (backfit) {
        CorrectorData left = trained;
        left.corrections_sensor_m -= predict_held_out(*without.fitted, trained).corrections_sensor_m;
        fold_fit = fit_lost_motion(chain, trained.joints_rad, trained.approach_sign,
                                   trained.fiducials_robot_m, deviation_robot_m(left), 1);
      } else {
        fold_fit = fit_lost_motion(chain, trained.joints_rad, trained.approach_sign,
                                   trained.fiducials_robot_m, deviation_robot_m(trained));
      }
    } catch (const InputError&) {
      continue;  // too few training fiducials for the plays and the trend
    }
    const FitOutcome with =
        staged.fitted->refit(without_lost_motion(trained, fold_fit.beta_rad), settings);
    if (!with.fitted) continue;
    const MethodPredictions p_without = predict_held_out(*without.fitted, held_out);
    const MethodPredictions p_with = predict_held_out(*with.fitted, held_out);
    const Points3 term_m = lost_motion_correction_sensor_m(
        chain, data.T_robot_sensor, held_out.joints_rad, held_out.approach_sign, fold_fit.beta_rad);
    for (std::size_t i = 0; i < test.size(); ++i) {
      if (p_without.stencils[i].status != StencilStatus::kOk ||
          p_with.stencils[i].status != StencilStatus::kOk)
        continue;
      const auto c = static_cast<Eigen::Index>(i);
      const Eigen::Vector3d measured = held_out.corrections_sensor_m.col(c);
      sum_without_m2 += (p_without.corrections_sensor_m.col(c) - measured).squaredNorm();
      sum_with_m2 += (p_with.corrections_sensor_m.col(c) + term_m.col(c) - measured).squaredNorm();
      ++term.n_compared;
    }
  }
  if (term.n_compared < kMinJudgedUnits) {
    term.reason = "not cross-validated (" + std::to_string(term.n_compared) +
                  " held-out fiducials predicted)";
    term.n_compared = 0;
    return term;
  }
  const auto n = static_cast<double>(term.n_compared);
  term.cv_rms_with_m = std::sqrt(sum_with_m2 / n);
  term.cv_rms_without_m = std::sqrt(sum_without_m2 / n);
  term.applied = term.cv_rms_with_m <= kEnterRatio * term.cv_rms_without_m;
  char line[200];
  std::snprintf(line, sizeof line, "cross-validated %s RMS %.4f mm with the term, %.4f mm without",
                to_string(judge), 1e3 * term.cv_rms_with_m, 1e3 * term.cv_rms_without_m);
  term.reason =
      std::string(line) + (term.applied ? ": applied" : ": not better by 5 %, not applied");
  if (!term.applied && backfit && term.cv_rms_with_m < term.cv_rms_without_m) {
    const Wald wald = wald_test(term);
    if (wald.dof > 0 &&
        wald.statistic >= chi_square_quantile_upper(kSignificanceTail, wald.dof)) {
      char significant[120];
      std::snprintf(significant, sizeof significant,
                    ", the plays significant (Wald %.1f on %d joints, p < 0.001): applied",
                    wald.statistic, wald.dof);
      term.applied = true;
      term.reason = line + std::string(significant);
    }
  }
  // A play is a gap: never negative, and a few arc-minutes even in a worn gear. Plays outside
  // that are the sign pattern standing in for something else (a KUKA cell without lost motion,
  // its locations' IK switching branches, fitted 90, -34 and 113 arc-min that cross-validation on
  // the fiducials' raster liked and targets visited in another order paid 4.5x for): auto
  // leaves such a term out.
  if (term.applied) {
    const std::string implausible = implausible_play(term);
    if (!implausible.empty()) {
      term.reason = std::string(term.reason, 0,
                                term.reason.size() - std::string(": applied").size()) +
                    implausible + ", not applied";
      term.applied = false;
    }
  }
  return term;
}

LostMotionPrediction predict_lost_motion(const kinematics::SerialChain& chain,
                                         const SimilarityTransform& T_robot_sensor,
                                         const LostMotionTerm& term,
                                         const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                                         const Eigen::Ref<const Eigen::MatrixXd>& approach_sign) {
  const Eigen::Index n = joints_rad.cols();
  const Eigen::Index n_joints = term.play_rad.size();
  VRREG_THROW_UNLESS(joints_rad.rows() == n_joints, "the model corrects lost motion of "
                                                        << n_joints << " joints, the query has "
                                                        << joints_rad.rows() << " joints");
  const bool known = approach_sign.size() > 0;
  VRREG_THROW_UNLESS(!known || (approach_sign.rows() == n_joints && approach_sign.cols() == n &&
                                (approach_sign.array().abs() <= 1.0).all()),
                     "the query's approach directions are "
                         << approach_sign.rows() << " x " << approach_sign.cols() << " for "
                         << n_joints << " joints x " << n << " points, or not signs (-1, 0, +1)");
  LostMotionPrediction out;
  out.variance_m2.resize(n);
  const Eigen::MatrixXd sign =
      known ? Eigen::MatrixXd(approach_sign) : Eigen::MatrixXd::Zero(n_joints, n);
  Points3 deviation_m(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const kinematics::Jacobian jac = kinematics::jacobian(chain, joints_rad.col(i));
    Eigen::Matrix3Xd js(3, n_joints);  // J_pos diag(s) / 2, the known directions only
    double unknown_m2 = 0.0;
    for (Eigen::Index j = 0; j < n_joints; ++j) {
      const Eigen::Vector3d column = 0.5 * jac.block<3, 1>(0, j);
      js.col(j) = sign(j, i) * column;
      // Either direction equally likely: the mean is none, the spread the term itself (and its
      // parameter uncertainty, which the known directions carry in the covariance below).
      if (sign(j, i) == 0.0) {
        unknown_m2 += column.squaredNorm() *
                      (term.play_rad(j) * term.play_rad(j) + term.covariance_rad2(j, j));
      }
    }
    deviation_m.col(i) = -js * term.play_rad;
    out.variance_m2(i) = (js * term.covariance_rad2 * js.transpose()).trace() + unknown_m2;
  }
  out.corrections_sensor_m =
      -(T_robot_sensor.rotation.transpose() * deviation_m) / T_robot_sensor.scale;
  return out;
}

}  // namespace detail
}  // namespace vrreg
