// SPDX-License-Identifier: Apache-2.0
#include "joint_error_design.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/marker_partials.hpp"

namespace vrreg::kinematics {
namespace {

Eigen::Vector3d marker_position_m(const SerialChain& chain, const JointRef& q_rad,
                                  const Eigen::Vector3d& p_flange_marker_m) {
  return chain.T_base_dh0() * (flange_in_dh0(chain, q_rad) * p_flange_marker_m);
}

Eigen::Vector3d marker_delta_m(const JointErrorModel::State& s, const Eigen::VectorXd& x) {
  if (!s.layout.marker) return Eigen::Vector3d::Zero();
  return x.segment<3>(s.layout.marker_column());
}

}  // namespace

int JointErrorLayout::joint_column(int joint) const {
  int c = 0;
  for (int i = 0; i < joint; ++i) c += degrees[static_cast<std::size_t>(i)] + 1;
  return c;
}
int JointErrorLayout::dh_column() const { return joint_column(n_joints()); }
int JointErrorLayout::marker_column() const { return dh_column() + (dh ? 3 * n_joints() : 0); }
int JointErrorLayout::trend_column() const { return marker_column() + (marker ? 3 : 0); }
int JointErrorLayout::n_trend_terms() const {
  constexpr int kTerms[] = {0, 1, 4, 10};
  return kTerms[trend_degree + 1];
}
int JointErrorLayout::periodic_column() const { return trend_column() + 3 * n_trend_terms(); }
int JointErrorLayout::n_columns() const {
  return periodic_column() + 2 * static_cast<int>(periodic.size());
}

std::pair<double, double> periodic_factors(const JointPeriodicTerm& term, double q_joint_rad) {
  const double w = term.omega_per_rad * q_joint_rad;
  return {std::sin(w), std::cos(w)};
}

void legendre_values(double u, int degree, double* out) {
  out[0] = 1.0;
  if (degree >= 1) out[1] = u;
  for (int k = 2; k <= degree; ++k) {
    out[k] = ((2.0 * k - 1.0) * u * out[k - 1] - (k - 1.0) * out[k - 2]) / k;
  }
}

double joint_unit(const JointErrorModel::State& s, int joint, double q_rad) {
  const double lo = s.q_lo_rad(joint);
  const double hi = s.q_hi_rad(joint);
  if (!(hi > lo)) return 0.0;  // a joint that never moved: only its offset is seen
  return std::clamp(2.0 * (q_rad - lo) / (hi - lo) - 1.0, -1.0, 1.0);
}

void trend_monomials(const JointErrorModel::State& s, const Eigen::Vector3d& p_nominal_m, int n,
                     double* out) {
  const Eigen::Vector3d v = (p_nominal_m - s.trend_centre_m) / s.trend_scale_m;
  const double all[10] = {1.0,           v.x(),         v.y(),         v.z(),
                          v.x() * v.x(), v.x() * v.y(), v.x() * v.z(), v.y() * v.y(),
                          v.y() * v.z(), v.z() * v.z()};
  std::copy(all, all + n, out);
}

JointVector joint_error_rad(const JointErrorModel::State& s, const Eigen::VectorXd& x,
                            const JointRef& q_rad) {
  const int n = s.layout.n_joints();
  JointVector dq = JointVector::Zero(n);
  double p[64];
  for (int i = 0; i < n; ++i) {
    const int degree = s.layout.degrees[static_cast<std::size_t>(i)];
    legendre_values(joint_unit(s, i, q_rad(i)), degree, p);
    const int c = s.layout.joint_column(i);
    for (int k = 0; k <= degree; ++k) dq(i) += x(c + k) * p[k];
  }
  int c = s.layout.periodic_column();
  for (const JointPeriodicTerm& t : s.layout.periodic) {
    const auto [sin_w, cos_w] = periodic_factors(t, q_rad(t.joint));
    dq(t.joint) += x(c) * sin_w + x(c + 1) * cos_w;
    c += 2;
  }
  return dq;
}

SerialChain perturbed_chain(const JointErrorModel::State& s, const Eigen::VectorXd& x) {
  if (!s.layout.dh) return s.nominal;
  std::vector<DhRow> rows = s.nominal.rows();
  const int c = s.layout.dh_column();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int k = c + 3 * static_cast<int>(i);
    rows[i].a_m += x(k);
    // A prismatic joint's d is its variable (its offset is the joint function's constant term):
    // its second geometric parameter is theta.
    (rows[i].prismatic() ? rows[i].theta_offset_rad : rows[i].d_m) += x(k + 1);
    rows[i].alpha_rad += x(k + 2);
  }
  return SerialChain(s.nominal.name(), std::move(rows), s.nominal.limits(), s.nominal.T_base_dh0(),
                     s.nominal.T_flange_tcp());
}

Eigen::Vector3d model_error_m(const JointErrorModel::State& s, const SerialChain& chain_x,
                              const Eigen::VectorXd& x, const JointRef& q_rad) {
  const JointVector q_actual = q_rad + joint_error_rad(s, x, q_rad);
  const Eigen::Vector3d p_nominal = marker_position_m(s.nominal, q_rad, s.p_flange_marker_m);
  Eigen::Vector3d e =
      marker_position_m(chain_x, q_actual, s.p_flange_marker_m + marker_delta_m(s, x)) - p_nominal;
  const int nt = s.layout.n_trend_terms();
  if (nt > 0) {
    double m[10];
    trend_monomials(s, p_nominal, nt, m);
    const int c = s.layout.trend_column();
    for (int axis = 0; axis < 3; ++axis) {
      for (int t = 0; t < nt; ++t) e(axis) += x(c + axis * nt + t) * m[t];
    }
  }
  return e;
}

void design_rows(const JointErrorModel::State& s, const SerialChain& chain_x,
                 const Eigen::VectorXd& x, const JointRef& q_rad,
                 Eigen::Ref<Eigen::MatrixXd> rows) {
  const JointErrorLayout& l = s.layout;
  rows.setZero();
  const JointVector q_actual = q_rad + joint_error_rad(s, x, q_rad);
  const MarkerPartials d =
      marker_partials(chain_x, q_actual, s.p_flange_marker_m + marker_delta_m(s, x));
  double p[64];
  for (int i = 0; i < l.n_joints(); ++i) {
    const int degree = l.degrees[static_cast<std::size_t>(i)];
    legendre_values(joint_unit(s, i, q_rad(i)), degree, p);
    const int c = l.joint_column(i);
    for (int k = 0; k <= degree; ++k) rows.col(c + k) = d.d_joint.col(i) * p[k];
    if (l.dh) {
      const int h = l.dh_column() + 3 * i;
      rows.col(h) = d.d_a.col(i);
      rows.col(h + 1) = chain_x.row(i).prismatic() ? d.d_theta.col(i) : d.d_d.col(i);
      rows.col(h + 2) = d.d_alpha.col(i);
    }
  }
  if (l.marker) rows.middleCols<3>(l.marker_column()) = d.R_base_flange;
  const int nt = l.n_trend_terms();
  if (nt > 0) {
    double m[10];
    // The trend is a function of the nominal position: linear in x, the same at every iterate.
    const Eigen::Vector3d p_nominal = marker_position_m(s.nominal, q_rad, s.p_flange_marker_m);
    trend_monomials(s, p_nominal, nt, m);
    for (int axis = 0; axis < 3; ++axis) {
      for (int t = 0; t < nt; ++t) rows(axis, l.trend_column() + axis * nt + t) = m[t];
    }
  }
  int c = l.periodic_column();
  for (const JointPeriodicTerm& t : l.periodic) {
    const auto [sin_w, cos_w] = periodic_factors(t, q_rad(t.joint));
    rows.col(c) = d.d_joint.col(t.joint) * sin_w;
    rows.col(c + 1) = d.d_joint.col(t.joint) * cos_w;
    c += 2;
  }
}

Eigen::MatrixXd design_matrix(const JointErrorModel::State& s, const Eigen::VectorXd& x,
                              const std::vector<JointVector>& q_rad) {
  const SerialChain chain_x = perturbed_chain(s, x);
  const auto n = static_cast<Eigen::Index>(q_rad.size());
  Eigen::MatrixXd a(3 * n, s.layout.n_columns());
  for (Eigen::Index j = 0; j < n; ++j) {
    design_rows(s, chain_x, x, q_rad[static_cast<std::size_t>(j)], a.middleRows<3>(3 * j));
  }
  return a;
}

Eigen::VectorXd inverse_column_norms(const Eigen::MatrixXd& a) {
  const Eigen::VectorXd norms = a.colwise().norm().transpose();
  const double negligible = 1e-10 * norms.maxCoeff();
  Eigen::VectorXd inverse = Eigen::VectorXd::Zero(norms.size());
  for (Eigen::Index c = 0; c < norms.size(); ++c) {
    if (norms(c) > negligible) inverse(c) = 1.0 / norms(c);
  }
  return inverse;
}

std::vector<int> cv_fold_of(int n, int folds, std::uint64_t seed) {
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  Random rng(seed);
  for (int i = n - 1; i > 0; --i) {  // Fisher-Yates with the project's portable generator
    const auto k = static_cast<std::size_t>(rng.below(static_cast<std::uint64_t>(i) + 1));
    std::swap(order[static_cast<std::size_t>(i)], order[k]);
  }
  std::vector<int> fold(static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r)
    fold[static_cast<std::size_t>(order[static_cast<std::size_t>(r)])] = r % folds;
  return fold;
}

}  // namespace vrreg::kinematics
