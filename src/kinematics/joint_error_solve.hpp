#pragma once
// The fitting steps of the joint-space error model shared by the fit, the degree choice and the
// cross-validation (joint_error_model.hpp).
#include <Eigen/Core>
#include <vector>

#include "joint_error_design.hpp"

namespace vrreg::kinematics {

/// A maximal set of independent columns of `a` (column-pivoted Householder QR on unit-norm
/// columns, pivots below `relative_rank_tolerance` of the largest dropped), ascending.
std::vector<Eigen::Index> independent_columns(const Eigen::MatrixXd& a,
                                              double relative_rank_tolerance);
/// Least-squares dx of |A dx - r| with only the columns `cols` free (the others 0).
Eigen::VectorXd solve_columns(const Eigen::MatrixXd& a, const std::vector<Eigen::Index>& cols,
                              const Eigen::VectorXd& r);

/// Checks the fit's inputs (throws InputError) and the state every fit shares: ranges of the
/// joints and the trend's centre and scale from these fiducials; layout without degrees.
JointErrorModel::State make_joint_error_state(
    const SerialChain& nominal, const std::vector<JointVector>& q_rad,
    const ConstPoints3Ref& error_robot_m, const JointErrorModelOptions& options,
    const std::optional<Eigen::Vector3d>& p_flange_marker_m);

/// Gauss-Newton (first step = the first-order solve) of `s` with its layout set; fills s.x and
/// s.linear and returns the rank of the last solve.
int fit_joint_error_parameters(JointErrorModel::State& s, const std::vector<JointVector>& q_rad,
                               const ConstPoints3Ref& error_robot_m,
                               const JointErrorModelOptions& options);

/// The model value of a fitted state at `q_rad` [m].
Eigen::Vector3d predict_joint_error_m(const JointErrorModel::State& s, const SerialChain& chain_x,
                                      const JointRef& q_rad);

/// Degrees per joint by K-fold CV of the first-order model (ridge solves of the fold Gram
/// matrices, a coordinate search over the degrees), and the best CV RMS [m].
struct JointDegreeChoice {
  std::vector<int> degrees;
  double cv_rms_m = 0.0;
};
JointDegreeChoice choose_joint_degrees(const JointErrorModel::State& s,
                                       const std::vector<JointVector>& q_rad,
                                       const ConstPoints3Ref& error_robot_m,
                                       const JointErrorModelOptions& options);

}  // namespace vrreg::kinematics
