// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/joint_error_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "joint_error_solve.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::kinematics {

JointErrorModel::JointErrorModel(std::shared_ptr<const State> state, Points3 residuals_m, int rank,
                                 std::vector<int> degrees, double selection_cv_rms_m)
    : state_(std::move(state)),
      residuals_m_(std::move(residuals_m)),
      rank_(rank),
      degrees_(std::move(degrees)),
      selection_cv_rms_m_(selection_cv_rms_m) {}

namespace {

// Every DH row's value at each joint vector of `nominal`'s variables.
std::vector<JointVector> row_values(const SerialChain& nominal,
                                    const std::vector<JointVector>& q_rad) {
  std::vector<JointVector> out;
  out.reserve(q_rad.size());
  for (std::size_t j = 0; j < q_rad.size(); ++j) {
    VRREG_THROW_UNLESS(q_rad[j].size() == nominal.n_joints(), "joint error model: fiducial "
                                                                  << j << " has " << q_rad[j].size()
                                                                  << " joints, the robot "
                                                                  << nominal.n_joints());
    out.push_back(nominal.row_values(q_rad[j]));
  }
  return out;
}

}  // namespace

JointErrorModel JointErrorModel::as_commanded_by(const SerialChain& commanded) const {
  auto s = std::make_shared<State>(*state_);
  s->commanded = commanded;
  return JointErrorModel(std::move(s), residuals_m_, rank_, degrees_, selection_cv_rms_m_);
}

int JointErrorModel::n_joints() const { return state_->commanded.n_joints(); }

std::pair<Eigen::VectorXd, Eigen::VectorXd> JointErrorModel::joint_range_rad() const {
  const SerialChain& c = state_->commanded;
  if (!c.coupled()) return {state_->q_lo_rad, state_->q_hi_rad};
  Eigen::VectorXd lo(c.n_joints()), hi(c.n_joints());
  std::vector<bool> done(static_cast<std::size_t>(c.n_joints()), false);
  for (int r = 0; r < c.n_rows(); ++r) {
    const JointCoupling& k = c.couplings().rows[static_cast<std::size_t>(r)];
    if (done[static_cast<std::size_t>(k.variable)]) continue;
    done[static_cast<std::size_t>(k.variable)] = true;
    const double a = (state_->q_lo_rad(r) - k.offset) / k.multiplier;
    const double b = (state_->q_hi_rad(r) - k.offset) / k.multiplier;
    lo(k.variable) = std::min(a, b);
    hi(k.variable) = std::max(a, b);
  }
  return {lo, hi};
}

JointVector JointErrorModel::rows_at(const JointRef& q_rad) const {
  state_->commanded.check_joints(q_rad, "joint error model prediction");
  return state_->commanded.row_values(q_rad);
}

JointErrorModel JointErrorModel::fit(const SerialChain& nominal,
                                     const std::vector<JointVector>& q_rad,
                                     const ConstPoints3Ref& error_robot_m,
                                     const JointErrorModelOptions& options,
                                     const std::optional<Eigen::Vector3d>& p_flange_marker_m) {
  // Joints that follow others keep errors of their own: the model of the physical joints (one
  // per DH row), asked at the rows' values.
  if (nominal.coupled()) {
    return fit(nominal.uncoupled(), row_values(nominal, q_rad), error_robot_m, options,
               p_flange_marker_m)
        .as_commanded_by(nominal);
  }
  auto s = std::make_shared<State>(
      make_joint_error_state(nominal, q_rad, error_robot_m, options, p_flange_marker_m));
  double selection_cv = std::numeric_limits<double>::quiet_NaN();
  if (options.joint_degrees.empty()) {
    const JointLayoutChoice choice = choose_joint_layout(*s, q_rad, error_robot_m, options);
    s->layout.degrees = choice.degrees;
    s->layout.periodic = choice.periodic;
    selection_cv = choice.cv_rms_m;
  } else {
    s->layout.degrees = options.joint_degrees;
    s->layout.periodic = options.periodic_terms;
  }
  const int rank = fit_joint_error_parameters(*s, q_rad, error_robot_m, options);
  const SerialChain chain_x = perturbed_chain(*s, s->x);
  Points3 residuals = error_robot_m;
  for (std::size_t j = 0; j < q_rad.size(); ++j) {
    residuals.col(static_cast<Eigen::Index>(j)) -= predict_joint_error_m(*s, chain_x, q_rad[j]);
  }
  std::vector<int> degrees = s->layout.degrees;
  return JointErrorModel(std::move(s), std::move(residuals), rank, std::move(degrees),
                         selection_cv);
}

Eigen::Vector3d JointErrorModel::predict_m(const JointRef& q_rad) const {
  const JointVector q_row = rows_at(q_rad);
  return predict_joint_error_m(*state_, perturbed_chain(*state_, state_->x), q_row);
}

Eigen::Vector3d JointErrorModel::predict_rotation_rad(const JointRef& q_rad) const {
  const JointVector q_row = rows_at(q_rad);
  const SerialChain chain_x = perturbed_chain(*state_, state_->x);
  const JointVector q_actual = q_row + joint_error_rad(*state_, state_->x, q_row);
  return rotation_log(forward_kinematics(chain_x, q_actual).linear() *
                      forward_kinematics(state_->nominal, q_row).linear().transpose());
}

Eigen::Vector3d JointErrorModel::predict_joint_angle_rotation_rad(const JointRef& q_rad) const {
  const JointVector q_row = rows_at(q_rad);
  const JointVector q_actual = q_row + joint_error_rad(*state_, state_->x, q_row);
  return rotation_log(forward_kinematics(state_->nominal, q_actual).linear() *
                      forward_kinematics(state_->nominal, q_row).linear().transpose());
}

JointVector JointErrorModel::joint_angle_errors_rad(const JointRef& q_rad) const {
  return joint_error_rad(*state_, state_->x, rows_at(q_rad));
}

Points3 JointErrorModel::predict_m(const std::vector<JointVector>& q_rad) const {
  const SerialChain chain_x = perturbed_chain(*state_, state_->x);
  Points3 out(3, static_cast<Eigen::Index>(q_rad.size()));
  for (std::size_t j = 0; j < q_rad.size(); ++j) {
    out.col(static_cast<Eigen::Index>(j)) =
        predict_joint_error_m(*state_, chain_x, rows_at(q_rad[j]));
  }
  return out;
}

double JointErrorModel::residual_rms_m() const {
  if (residuals_m_.cols() == 0) return 0.0;
  return std::sqrt(residuals_m_.colwise().squaredNorm().mean());
}

const Eigen::VectorXd& JointErrorModel::parameters() const { return state_->x; }

const std::vector<JointPeriodicTerm>& JointErrorModel::periodic_terms() const {
  return state_->layout.periodic;
}

double joint_error_cv_rms_m(const SerialChain& nominal, const std::vector<JointVector>& q_rad,
                            const ConstPoints3Ref& error_robot_m,
                            const JointErrorModelOptions& options,
                            const std::optional<Eigen::Vector3d>& p_flange_marker_m) {
  if (nominal.coupled()) {  // the physical joints' model, as JointErrorModel::fit
    return joint_error_cv_rms_m(nominal.uncoupled(), row_values(nominal, q_rad), error_robot_m,
                                options, p_flange_marker_m);
  }
  JointErrorModelOptions fixed = options;
  if (fixed.joint_degrees.empty()) {
    const JointErrorModel::State s =
        make_joint_error_state(nominal, q_rad, error_robot_m, options, p_flange_marker_m);
    const JointLayoutChoice choice = choose_joint_layout(s, q_rad, error_robot_m, options);
    fixed.joint_degrees = choice.degrees;
    fixed.periodic_terms = choice.periodic;
  }
  const int n = static_cast<int>(q_rad.size());
  VRREG_THROW_UNLESS(n >= options.cv_folds, "joint error model: " << n << " fiducials for "
                                                                  << options.cv_folds << " folds");
  const std::vector<int> fold = cv_fold_of(n, options.cv_folds, options.cv_seed);
  double sum_sq = 0.0;
  for (int f = 0; f < options.cv_folds; ++f) {
    std::vector<JointVector> q_train;
    std::vector<JointVector> q_test;
    std::vector<Eigen::Index> train;
    std::vector<Eigen::Index> test;
    for (int j = 0; j < n; ++j) {
      const bool held_out = fold[static_cast<std::size_t>(j)] == f;
      (held_out ? q_test : q_train).push_back(q_rad[static_cast<std::size_t>(j)]);
      (held_out ? test : train).push_back(j);
    }
    const Points3 e_train = error_robot_m(Eigen::all, train);
    const JointErrorModel model =
        JointErrorModel::fit(nominal, q_train, e_train, fixed, p_flange_marker_m);
    sum_sq +=
        (error_robot_m(Eigen::all, test) - model.predict_m(q_test)).colwise().squaredNorm().sum();
  }
  return std::sqrt(sum_sq / n);
}

}  // namespace vrreg::kinematics
