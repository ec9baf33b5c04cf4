// SPDX-License-Identifier: Apache-2.0
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

/// Joint values closer than this are one sample of that joint's error function.
constexpr double kSameAngleRad = 1e-6;
/// How many distinct values (kSameAngleRad apart) joint `joint` takes over `q_rad`.
int distinct_joint_values(const std::vector<JointVector>& q_rad, int joint);
/// The largest Legendre degree of a joint sampled at `n_distinct` angles: a third of them.
inline int joint_degree_cap(int n_distinct) { return n_distinct > 1 ? (n_distinct - 1) / 3 : 0; }

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

/// Candidate periodic terms (joint_error_periodic.cpp): a greedy periodogram of what a smooth
/// model (low Legendre degrees, DH, marker, trend, the terms found so far) leaves at the
/// fiducials, each term kept while its drop of the residual is beyond what noise would give.
std::vector<JointPeriodicTerm> find_periodic_terms(const JointErrorModel::State& s,
                                                   const std::vector<JointVector>& q_rad,
                                                   const ConstPoints3Ref& error_robot_m,
                                                   const JointErrorModelOptions& options);

/// The layout of an automatic fit: degrees by CV (choose_joint_degrees), with the periodic terms
/// of find_periodic_terms when they lower the CV RMS (or the given terms), and its CV RMS [m].
struct JointLayoutChoice {
  std::vector<int> degrees;
  std::vector<JointPeriodicTerm> periodic;
  double cv_rms_m = 0.0;
};
JointLayoutChoice choose_joint_layout(const JointErrorModel::State& s,
                                      const std::vector<JointVector>& q_rad,
                                      const ConstPoints3Ref& error_robot_m,
                                      const JointErrorModelOptions& options);

}  // namespace vrreg::kinematics
