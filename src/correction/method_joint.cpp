// SPDX-License-Identifier: Apache-2.0
// The joint-space error model (kinematics/joint_error_model.hpp) as a correction method. It
// models e = y_observed - y_nominal in the robot frame as a function of the commanded joints; a
// corrected target is R X + tau - e(q), i.e. the sensor-frame correction -R' e / s.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>

#include "joint_gaps.hpp"
#include "method_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"

namespace vrreg::detail {
namespace {

std::vector<kinematics::JointVector> joint_columns(const Eigen::Ref<const Eigen::MatrixXd>& q_rad,
                                                   Eigen::Index begin, Eigen::Index end) {
  std::vector<kinematics::JointVector> out;
  out.reserve(static_cast<std::size_t>(end - begin));
  for (Eigen::Index j = begin; j < end; ++j) out.emplace_back(q_rad.col(j));
  return out;
}

// A commanded joint may leave the fiducials' range of that joint by this share of the range (plus
// a milliradian) before the model is outside its support: its angle-error functions are held at
// the range's ends, which is a guess a little way out and none far away.
constexpr double kJointRangeMargin = 0.05;
constexpr double kJointSlackRad = 1e-3;

class JointMethod;
std::unique_ptr<const JointMethod> fit_joint_model(
    const CorrectorData& data, const kinematics::JointErrorModelOptions& options);

class JointMethod final : public FittedMethod {
 public:
  JointMethod(kinematics::JointErrorModel model, const SimilarityTransform& T, SupportBox support,
              JointGaps gaps = {})
      : model_(std::move(model)), T_robot_sensor_(T), support_(support), gaps_(std::move(gaps)) {
    const auto [q_lo_rad, q_hi_rad] = model_.joint_range_rad();
    const Eigen::VectorXd margin =
        (kJointRangeMargin * (q_hi_rad - q_lo_rad)).array() + kJointSlackRad;
    q_lo_rad_ = q_lo_rad - margin;
    q_hi_rad_ = q_hi_rad + margin;
  }

  [[nodiscard]] InterpolationMethod method() const override { return InterpolationMethod::kJoint; }
  [[nodiscard]] MethodNeeds needs() const override { return {.joints = true}; }
  [[nodiscard]] bool judges_gaps() const override { return gaps_.judges(); }
  [[nodiscard]] const kinematics::JointErrorModel& model() const { return model_; }
  /// The same fitted model judging these gaps.
  [[nodiscard]] std::unique_ptr<const JointMethod> with_gaps(JointGaps gaps) const {
    return std::make_unique<const JointMethod>(model_, T_robot_sensor_, support_, std::move(gaps));
  }

  [[nodiscard]] FitOutcome refit(const CorrectorData& subset,
                                 const MethodSettings&) const override {
    kinematics::JointErrorModelOptions options;
    options.joint_degrees = model_.joint_degrees();
    options.periodic_terms = model_.periodic_terms();
    return FitOutcome{fit_joint_model(subset, options), {}};
  }

  [[nodiscard]] std::optional<Eigen::Vector3d> rotation_error_rad(
      const Eigen::Ref<const Eigen::VectorXd>& joints_rad, bool joint_angles_only) const override {
    return joint_angles_only ? model_.predict_joint_angle_rotation_rad(joints_rad)
                             : model_.predict_rotation_rad(joints_rad);
  }

  [[nodiscard]] std::optional<Eigen::VectorXd> joint_angle_errors_rad(
      const Eigen::Ref<const Eigen::VectorXd>& joints_rad) const override {
    return Eigen::VectorXd(model_.joint_angle_errors_rad(joints_rad));
  }

  void check_query(const MethodQuery& query) const override {
    const int n = model_.n_joints();
    VRREG_THROW_UNLESS(query.joints_rad.cols() == query.registered_robot_m.cols() &&
                           query.joints_rad.rows() == n,
                       "joint interpolation needs every target's joint angles ("
                           << n << " per target, got " << query.joints_rad.rows() << ")");
  }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    const Points3 e_robot_m = model_.predict_m(joint_columns(query.joints_rad, begin, end));
    out.corrections_sensor_m.middleCols(begin, end - begin) =
        -(T_robot_sensor_.rotation.transpose() * e_robot_m) / T_robot_sensor_.scale;
    for (Eigen::Index i = begin; i < end; ++i) {
      bool inside = support_.contains(query.registered_robot_m.col(i)) &&
                    (query.joints_rad.col(i).array() >= q_lo_rad_.array()).all() &&
                    (query.joints_rad.col(i).array() <= q_hi_rad_.array()).all();
      if (inside && gaps_.judges()) {
        const JointGaps::Answer gap = gaps_.at(query.joints_rad.col(i));
        inside = gap.unmeasured_m == 0.0;
        if (out.gap_sd_m.size() > 0) out.gap_sd_m(i) = gap.sd_m;
      }
      if (inside) {
        out.stencils[static_cast<std::size_t>(i)] = Stencil{};
      } else {
        out.stencils[static_cast<std::size_t>(i)] = flagged_stencil(StencilStatus::kOutsideSupport);
        out.corrections_sensor_m.col(i).setZero();
      }
    }
  }

  // The joint model reads the joints: a target whose joints leave the range seen in the
  // fiducials moved by an angle, not a length (infinity: the widest sd); one in a gap nothing
  // measured, by the marker's motion from the nearest measured value.
  [[nodiscard]] std::optional<Eigen::VectorXd> clamp_to_support(
      Points3& registered_robot_m, Eigen::MatrixXd& joints_rad) const override {
    Eigen::VectorXd moved_m = support_.clamp(registered_robot_m);
    for (Eigen::Index i = 0; i < joints_rad.cols(); ++i) {
      const Eigen::VectorXd q = joints_rad.col(i);
      joints_rad.col(i) = q.cwiseMax(q_lo_rad_).cwiseMin(q_hi_rad_);
      if (joints_rad.col(i) != q) {
        moved_m(i) = std::numeric_limits<double>::infinity();
      } else if (gaps_.judges()) {
        moved_m(i) = std::max(moved_m(i), gaps_.at(q).unmeasured_m);
      }
    }
    return moved_m;
  }

  [[nodiscard]] std::string describe() const override {
    std::ostringstream out;
    out << "joint-space model: per-joint Legendre angle errors (degrees";
    for (const int d : model_.joint_degrees()) out << ' ' << d;
    out << ")";
    const char* sep = ", cyclic errors (period): ";
    for (const kinematics::JointPeriodicTerm& t : model_.periodic_terms()) {
      out << sep << "joint " << t.joint + 1 << " " << std::setprecision(4)
          << 360.0 / t.omega_per_rad << " deg";
      sep = ", ";
    }
    out << ", DH and marker deltas, quadratic trend; rank " << model_.rank() << " of "
        << model_.n_parameters() << " parameters";
    const char* gap = "; gaps between the fiducials' values of joint ";
    for (Eigen::Index i = 0; i < gaps_.gap_error_m().size(); ++i) {
      const double e = gaps_.gap_error_m()(i);
      if (e == JointGaps::kNoWideGap) continue;
      out << gap << i + 1;
      if (e >= 0.0) {
        out << " (held out: " << std::setprecision(3) << 1e3 * e << " mm)";
      } else {
        out << " (unmeasured: outside the support)";
      }
      gap = ", ";
    }
    return out.str();
  }

  [[nodiscard]] MethodState save() const override {
    const kinematics::JointErrorModelParameters p = model_.saved();
    MethodState s("joint");
    Eigen::MatrixXd degrees(static_cast<Eigen::Index>(p.joint_degrees.size()), 1);
    for (std::size_t i = 0; i < p.joint_degrees.size(); ++i)
      degrees(static_cast<Eigen::Index>(i), 0) = p.joint_degrees[i];
    s.put("joint_degrees", std::move(degrees));
    Eigen::MatrixXd periodic(2, static_cast<Eigen::Index>(p.periodic_terms.size()));
    for (std::size_t m = 0; m < p.periodic_terms.size(); ++m) {
      periodic(0, static_cast<Eigen::Index>(m)) = p.periodic_terms[m].joint;
      periodic(1, static_cast<Eigen::Index>(m)) = p.periodic_terms[m].omega_per_rad;
    }
    s.put("periodic_joint_omega_per_rad", std::move(periodic));
    s.put("dh_deltas", p.dh_deltas ? 1.0 : 0.0);
    s.put("marker_offset", p.marker_offset ? 1.0 : 0.0);
    s.put("trend_degree", p.trend_degree);
    s.put("q_lo_rad", Eigen::MatrixXd(p.q_lo_rad));
    s.put("q_hi_rad", Eigen::MatrixXd(p.q_hi_rad));
    s.put("trend_centre_m", Eigen::MatrixXd(p.trend_centre_m));
    s.put("trend_scale_m", p.trend_scale_m);
    s.put("p_flange_marker_m", Eigen::MatrixXd(p.p_flange_marker_m));
    s.put("linear", p.linear ? 1.0 : 0.0);
    s.put("parameters", Eigen::MatrixXd(p.x));
    s.put("rank", p.rank);
    if (std::isfinite(p.selection_cv_rms_m)) s.put("selection_cv_rms_m", p.selection_cv_rms_m);
    if (gaps_.judges()) s.put("gap_error_m", Eigen::MatrixXd(gaps_.gap_error_m()));
    return s;
  }

 private:
  kinematics::JointErrorModel model_;
  SimilarityTransform T_robot_sensor_;
  SupportBox support_;
  Eigen::VectorXd q_lo_rad_;  ///< the joints' fitted ranges with their margins
  Eigen::VectorXd q_hi_rad_;
  JointGaps gaps_;  ///< the ranges' wide gaps (joint_gaps.hpp)
};

// Least squares needs redundancy: with fewer equations per identified parameter the fit follows
// the noise, and its cross-validation, on 4/5 of the fiducials, is no guide to it. The 27-fiducial
// cube of A1 identifies 42-52 parameters from 81 equations: on seeds 1-8 it corrected the targets to
// 0.16-2.6 mm (octuplet RRBC 0.18-0.27 mm), its sd up to 7 times too large. The thinned A1 grid
// identifies ~60 from 630 and reaches the noise floor. Only the fit on all fiducials is checked:
// cross-validation refits the same parameters on fewer.
constexpr int kMinEquationsPerParameter = 3;

// Below this the fiducials' nominal positions are the robot's forward kinematics to one marker.
constexpr double kNominalMismatchM = 1e-4;

// Where the marker sits on the flange, from the fiducials' nominal positions Y_j = T_flange(q_j) p
// (least squares: the mean of R_j' (Y_j - t_j)); so the robot needs no tool of its own. Throws
// when the nominal positions are not this robot's kinematics (a wrong robot: a caller's error).
Eigen::Vector3d marker_on_flange_m(const CorrectorData& data) {
  const kinematics::SerialChain flange = data.robot->with_tool(Eigen::Isometry3d::Identity());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::vector<Eigen::Isometry3d> poses;
  for (Eigen::Index j = 0; j < data.size(); ++j) {
    poses.push_back(kinematics::forward_kinematics(flange, data.joints_rad.col(j)));
    sum += poses.back().linear().transpose() *
           (data.fiducials_robot_m.col(j) - poses.back().translation());
  }
  const Eigen::Vector3d p_m = sum / static_cast<double>(data.size());
  double worst_m = 0.0;
  for (Eigen::Index j = 0; j < data.size(); ++j) {
    worst_m = std::max(worst_m, (poses[static_cast<std::size_t>(j)] * p_m -
                                 data.fiducials_robot_m.col(j)).norm());
  }
  VRREG_THROW_UNLESS(worst_m <= kNominalMismatchM,
                     "the fiducials' robot positions are not "
                         << data.robot->name()
                         << "'s forward kinematics of their joints to one marker (off by up to "
                         << worst_m * 1e3 << " mm): another `robot`?");
  return p_m;
}

// In a large cell the joint model is fitted on this many fiducials, drawn with a fixed seed: its
// few hundred parameters are fixed by 3 x 5 000 equations to a few micrometres (the noise over
// the square root of the redundancy), while its fit (periodic-term search, degree choice, QR
// of 3J rows) grows with J: 10^5 fiducials took minutes and 1.1 GiB.
constexpr Eigen::Index kLargeCellJointFit = 5000;

// The fiducials a joint model is fitted on: all of them, or in a large cell a seeded sample
// in their order.
std::vector<Eigen::Index> joint_fit_sample(Eigen::Index n) {
  std::vector<Eigen::Index> all(static_cast<std::size_t>(n));
  std::iota(all.begin(), all.end(), Eigen::Index{0});
  if (n <= kLargeCellFiducials) return all;
  Random rng(1);
  for (std::size_t i = 0; i < static_cast<std::size_t>(kLargeCellJointFit); ++i) {
    std::swap(all[i], all[i + static_cast<std::size_t>(rng.below(all.size() - i))]);
  }
  all.resize(static_cast<std::size_t>(kLargeCellJointFit));
  std::sort(all.begin(), all.end());
  return all;
}

std::unique_ptr<const JointMethod> fit_joint_model(
    const CorrectorData& all, const kinematics::JointErrorModelOptions& options) {
  const bool sampled = all.size() > kLargeCellFiducials;
  const CorrectorData sample = sampled ? all.subset(joint_fit_sample(all.size())) : CorrectorData{};
  const CorrectorData& data = sampled ? sample : all;
  VRREG_THROW_UNLESS(data.robot && data.joints_rad.rows() == data.robot->n_joints(),
                     "joint interpolation needs the fiducials' joint angles and the robot");
  const Eigen::Vector3d p_flange_marker_m = marker_on_flange_m(data);
  // The errors the arm made, as the registration sees them: y_observed - y_nominal.
  const Points3 error_robot_m = data.registered_robot_m - data.fiducials_robot_m;
  return std::make_unique<const JointMethod>(
      kinematics::JointErrorModel::fit(*data.robot,
                                       joint_columns(data.joints_rad, 0, data.size()),
                                       error_robot_m, options, p_flange_marker_m),
      data.T_robot_sensor, field_support(all.fiducials_robot_m));
}

std::string joint_unavailable(const CorrectorData& data, const MethodSettings&) {
  if (!data.has_joints()) return "the fiducials have no joint angles";
  if (!data.robot) return "no robot given (`robot`)";
  if (data.joints_rad.rows() != data.robot->n_joints()) {
    return "the fiducials have " + std::to_string(data.joints_rad.rows()) +
           " joint angles, the robot " + std::to_string(data.robot->n_joints());
  }
  if (data.size() < kMinFieldModelFiducials) return "fewer than 12 fiducials";
  return {};
}

// A gap's error is measured only at two or more held-out values: the fiducials at one value share
// one sample of a ripple's phase (three carriage positions, seeds 1-5: the middle one's held-out
// error was 0.026-0.17 mm, the targets' 0.16 mm RMS). From k values its mean square is raised by
// 1 / k: few say little.
constexpr int kMinHeldOutValues = 2;
constexpr double kFewValuesInflation = 1.0;

// The gaps of `data`'s joint ranges, each wide one measured by holding out the fiducials at its
// interior values and predicting them with the model refitted (its degrees and periodic terms
// kept) on the rest: the RMS of those errors beyond the full model's own at them.
JointGaps measured_gaps(const CorrectorData& data, const JointMethod& fitted) {
  const kinematics::JointErrorModel& model = fitted.model();
  JointGaps gaps(data, model.saved().p_flange_marker_m);
  kinematics::JointErrorModelOptions options;
  options.joint_degrees = model.joint_degrees();
  options.periodic_terms = model.periodic_terms();
  const Points3 error_robot_m = data.registered_robot_m - data.fiducials_robot_m;
  for (int i = 0; i < gaps.gap_error_m().size(); ++i) {
    if (gaps.gap_error_m()(i) != JointGaps::kUnmeasured) continue;
    double held_sq_m2 = 0.0;
    double own_sq_m2 = 0.0;
    Eigen::Index count = 0;
    int values = 0;
    const std::vector<double> interior = gaps.interior_values(i);
    if (std::ssize(interior) < kMinHeldOutValues) continue;  // unmeasured: outside the support
    for (const double value : interior) {
      const std::vector<Eigen::Index> held = gaps.at_value(data.joints_rad, i, value);
      std::vector<Eigen::Index> kept;
      for (Eigen::Index j = 0, h = 0; j < data.size(); ++j) {
        if (h < std::ssize(held) && held[static_cast<std::size_t>(h)] == j) {
          ++h;
        } else {
          kept.push_back(j);
        }
      }
      std::unique_ptr<const JointMethod> refit;
      try {
        refit = fit_joint_model(data.subset(kept), options);
      } catch (const InputError&) {
        continue;  // the rest cannot carry the model: this value measures nothing
      }
      ++values;
      for (const Eigen::Index j : held) {
        const Eigen::VectorXd q = data.joints_rad.col(j);
        held_sq_m2 += (refit->model().predict_m(q) - error_robot_m.col(j)).squaredNorm();
        own_sq_m2 += (model.predict_m(q) - error_robot_m.col(j)).squaredNorm();
        ++count;
      }
    }
    if (count > 0 && values >= kMinHeldOutValues) {
      const double mean_sq_m2 = std::max(0.0, (held_sq_m2 - own_sq_m2) / static_cast<double>(count));
      gaps.set_error(i, std::sqrt(mean_sq_m2 * (1.0 + kFewValuesInflation / values)));
    }
  }
  return gaps;
}

FitOutcome fit_joint(const CorrectorData& data, const MethodSettings& /*settings*/) {
  std::unique_ptr<const JointMethod> fitted =
      fit_joint_model(data, {});
  const int rank = fitted->model().rank();
  const Eigen::Index equations = 3 * data.size();
  if (equations < kMinEquationsPerParameter * rank) {
    std::ostringstream why;
    why << "the joint-space model identifies " << rank << " parameters from " << data.size()
        << " fiducials (" << equations << " equations); it needs at least "
        << kMinEquationsPerParameter << " equations per parameter, i.e. "
        << (kMinEquationsPerParameter * rank + 2) / 3 << " fiducials";
    return not_applicable(why.str());
  }
  return FitOutcome{fitted->with_gaps(measured_gaps(data, *fitted)), {}};
}

std::unique_ptr<const FittedMethod> restore_joint(const MethodState& state,
                                                  const CorrectorData& data,
                                                  const MethodSettings& /*settings*/) {
  VRREG_THROW_UNLESS(data.robot, "the saved joint corrector needs the model's robot");
  kinematics::JointErrorModelParameters p;
  const int n = data.robot->n_rows();  // one per physical joint
  const Eigen::MatrixXd& degrees = state.array("joint_degrees", n, 1);
  for (int i = 0; i < n; ++i) {
    VRREG_THROW_UNLESS(degrees(i, 0) == std::floor(degrees(i, 0)) && degrees(i, 0) >= 0,
                       "the saved joint corrector's degrees are not whole numbers >= 0");
    p.joint_degrees.push_back(static_cast<int>(degrees(i, 0)));
  }
  const Eigen::MatrixXd& periodic = state.array("periodic_joint_omega_per_rad", 2, -1);
  for (Eigen::Index m = 0; m < periodic.cols(); ++m) {
    VRREG_THROW_UNLESS(periodic(0, m) == std::floor(periodic(0, m)) && periodic(0, m) >= 0 &&
                           periodic(0, m) < n,
                       "the saved joint corrector's periodic term " << m << " names no joint");
    p.periodic_terms.push_back({static_cast<int>(periodic(0, m)), periodic(1, m)});
  }
  p.dh_deltas = state.integer("dh_deltas", 0, 1) == 1;
  p.marker_offset = state.integer("marker_offset", 0, 1) == 1;
  p.trend_degree = static_cast<int>(state.integer("trend_degree", -1, 2));
  p.q_lo_rad = state.array("q_lo_rad", n, 1);
  p.q_hi_rad = state.array("q_hi_rad", n, 1);
  p.trend_centre_m = state.array("trend_centre_m", 3, 1);
  p.trend_scale_m = state.number("trend_scale_m");
  p.p_flange_marker_m = state.array("p_flange_marker_m", 3, 1);
  p.linear = state.integer("linear", 0, 1) == 1;
  p.x = state.array("parameters", -1, 1);
  p.rank = static_cast<int>(state.integer("rank", 0, 1 << 30));
  p.selection_cv_rms_m = state.has("selection_cv_rms_m")
                             ? state.number("selection_cv_rms_m")
                             : std::numeric_limits<double>::quiet_NaN();
  // A model saved before gaps were judged judges none.
  const Eigen::VectorXd gap_error_m =
      state.has("gap_error_m") ? Eigen::VectorXd(state.array("gap_error_m", n, 1))
                               : Eigen::VectorXd::Constant(n, JointGaps::kNoWideGap);
  return std::make_unique<const JointMethod>(
      kinematics::JointErrorModel::restore(*data.robot, p), data.T_robot_sensor,
      field_support(data.fiducials_robot_m), JointGaps(data, p.p_flange_marker_m, gap_error_m));
}

}  // namespace

CorrectionMethod joint_method() {
  return {InterpolationMethod::kJoint, true, joint_unavailable, fit_joint, restore_joint};
}

}  // namespace vrreg::detail
