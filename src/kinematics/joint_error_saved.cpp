// SPDX-License-Identifier: Apache-2.0
// Saving and restoring a fitted joint-space error model (joint_error_model.hpp): its state is
// small (the parameters, the joints' ranges, the trend's frame), so a model file carries it and a
// corrector needs no fit.
#include <cmath>
#include <limits>

#include "joint_error_design.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"

namespace vrreg::kinematics {

JointErrorModelParameters JointErrorModel::saved() const {
  JointErrorModelParameters p;
  const State& s = *state_;
  p.joint_degrees = s.layout.degrees;
  p.periodic_terms = s.layout.periodic;
  p.dh_deltas = s.layout.dh;
  p.marker_offset = s.layout.marker;
  p.trend_degree = s.layout.trend_degree;
  p.q_lo_rad = s.q_lo_rad;
  p.q_hi_rad = s.q_hi_rad;
  p.trend_centre_m = s.trend_centre_m;
  p.trend_scale_m = s.trend_scale_m;
  p.p_flange_marker_m = s.p_flange_marker_m;
  p.linear = s.linear;
  p.x = s.x;
  p.rank = rank_;
  p.selection_cv_rms_m = selection_cv_rms_m_;
  return p;
}

JointErrorModel JointErrorModel::restore(const SerialChain& nominal,
                                         const JointErrorModelParameters& p) {
  if (nominal.coupled()) return restore(nominal.uncoupled(), p).as_commanded_by(nominal);
  const int n = nominal.n_joints();
  VRREG_THROW_UNLESS(static_cast<int>(p.joint_degrees.size()) == n &&
                         p.q_lo_rad.size() == n && p.q_hi_rad.size() == n,
                     "joint error model: the saved model is for "
                         << p.joint_degrees.size() << " joints, the robot " << nominal.name()
                         << " has " << n);
  for (int i = 0; i < n; ++i) {
    VRREG_THROW_UNLESS(p.joint_degrees[static_cast<std::size_t>(i)] >= 0 &&
                           p.joint_degrees[static_cast<std::size_t>(i)] <= 1000 &&
                           std::isfinite(p.q_lo_rad(i)) && std::isfinite(p.q_hi_rad(i)) &&
                           p.q_lo_rad(i) <= p.q_hi_rad(i),
                       "joint error model: the saved degree or range of joint " << i + 1
                                                                                << " is invalid");
  }
  for (const JointPeriodicTerm& t : p.periodic_terms) {
    VRREG_THROW_UNLESS(t.joint >= 0 && t.joint < n && std::isfinite(t.omega_per_rad) &&
                           t.omega_per_rad > 0.0,
                       "joint error model: a saved periodic term is invalid");
  }
  VRREG_THROW_UNLESS(p.trend_degree >= -1 && p.trend_degree <= 2 &&
                         std::isfinite(p.trend_scale_m) && p.trend_scale_m > 0.0 &&
                         p.trend_centre_m.allFinite() && p.p_flange_marker_m.allFinite(),
                     "joint error model: the saved trend or marker is invalid");
  auto s = std::make_shared<State>(nominal);
  s->layout.degrees = p.joint_degrees;
  s->layout.periodic = p.periodic_terms;
  s->layout.dh = p.dh_deltas;
  s->layout.marker = p.marker_offset;
  s->layout.trend_degree = p.trend_degree;
  s->q_lo_rad = p.q_lo_rad;
  s->q_hi_rad = p.q_hi_rad;
  s->trend_centre_m = p.trend_centre_m;
  s->trend_scale_m = p.trend_scale_m;
  s->p_flange_marker_m = p.p_flange_marker_m;
  s->linear = p.linear;
  VRREG_THROW_UNLESS(p.x.size() == s->layout.n_columns() && p.x.allFinite(),
                     "joint error model: " << p.x.size() << " saved parameters, the layout has "
                                           << s->layout.n_columns());
  s->x = p.x;
  return JointErrorModel(std::move(s), Points3(3, 0), p.rank, p.joint_degrees,
                         p.selection_cv_rms_m);
}

}  // namespace vrreg::kinematics
