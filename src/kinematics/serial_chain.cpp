// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/serial_chain.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/pose.hpp"

namespace vrreg::kinematics {
namespace {

using units::kPi;

bool is_identity(const Eigen::Isometry3d& t) { return t.matrix() == Eigen::Matrix4d::Identity(); }

bool near(double value, double expected, double tolerance) {
  return std::abs(value - expected) <= tolerance;
}

bool angle_near(double value_rad, double expected_rad, double tolerance) {
  return std::abs(wrap_angle(value_rad - expected_rad)) <= tolerance;
}

bool all_revolute(const std::vector<DhRow>& rows) {
  return std::none_of(rows.begin(), rows.end(), [](const DhRow& r) { return r.prismatic(); });
}

bool has_ur_structure(const std::vector<DhRow>& rows, double tol) {
  if (rows.size() != 6 || !all_revolute(rows)) return false;
  const double alpha[6] = {kPi / 2, 0.0, 0.0, kPi / 2, -kPi / 2, 0.0};
  for (std::size_t i = 0; i < 6; ++i) {
    if (!angle_near(rows[i].alpha_rad, alpha[i], tol)) return false;
  }
  return near(rows[0].a_m, 0.0, tol) && near(rows[3].a_m, 0.0, tol) &&
         near(rows[4].a_m, 0.0, tol) && near(rows[5].a_m, 0.0, tol) &&
         !near(rows[1].a_m, 0.0, tol) && !near(rows[2].a_m, 0.0, tol);
}

bool has_lwr_structure(const std::vector<DhRow>& rows, double tol) {
  if (rows.size() != 7 || !all_revolute(rows)) return false;
  const double alpha[7] = {kPi / 2, -kPi / 2, -kPi / 2, kPi / 2, kPi / 2, -kPi / 2, 0.0};
  for (std::size_t i = 0; i < 7; ++i) {
    if (!angle_near(rows[i].alpha_rad, alpha[i], tol) || !near(rows[i].a_m, 0.0, tol)) {
      return false;
    }
  }
  return near(rows[1].d_m, 0.0, tol) && near(rows[3].d_m, 0.0, tol) &&
         near(rows[5].d_m, 0.0, tol) && !near(rows[2].d_m, 0.0, tol) &&
         !near(rows[4].d_m, 0.0, tol);
}

}  // namespace

const char* to_string(ChainFamily family) {
  switch (family) {
    case ChainFamily::kUr:
      return "ur";
    case ChainFamily::kLwr:
      return "lwr";
    case ChainFamily::kGeneric:
      break;
  }
  return "generic";
}

ChainFamily detect_family(const std::vector<DhRow>& rows, double tolerance) {
  if (has_ur_structure(rows, tolerance)) return ChainFamily::kUr;
  if (has_lwr_structure(rows, tolerance)) return ChainFamily::kLwr;
  return ChainFamily::kGeneric;
}

SerialChain::SerialChain(std::string name, std::vector<DhRow> rows, std::vector<JointLimits> limits,
                         const Eigen::Isometry3d& T_base_dh0, const Eigen::Isometry3d& T_flange_tcp)
    : name_(std::move(name)),
      rows_(std::move(rows)),
      limits_(std::move(limits)),
      T_base_dh0_(T_base_dh0),
      T_flange_tcp_(T_flange_tcp) {
  VRREG_THROW_UNLESS(!rows_.empty() && rows_.size() <= static_cast<std::size_t>(kMaxJoints),
                     "robot '" << name_ << "': a chain needs 1 to " << kMaxJoints << " joints, got "
                               << rows_.size());
  VRREG_THROW_UNLESS(limits_.size() == rows_.size(), "robot '" << name_ << "': " << rows_.size()
                                                               << " DH rows but " << limits_.size()
                                                               << " joint limits");
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const DhRow& r = rows_[i];
    VRREG_THROW_UNLESS(std::isfinite(r.a_m) && std::isfinite(r.alpha_rad) && std::isfinite(r.d_m) &&
                           std::isfinite(r.theta_offset_rad),
                       "robot '" << name_ << "': DH row " << i + 1 << " has a non-finite value (a="
                                 << r.a_m << ", alpha=" << r.alpha_rad << ", d=" << r.d_m
                                 << ", theta_offset=" << r.theta_offset_rad << ")");
    const JointLimits& l = limits_[i];
    VRREG_THROW_UNLESS(
        std::isfinite(l.lower_rad) && std::isfinite(l.upper_rad) && l.lower_rad < l.upper_rad,
        "robot '" << name_ << "': joint " << i + 1
                  << " limits must be finite with lower < upper, got [" << l.lower_rad << ", "
                  << l.upper_rad << "] rad");
  }
  const std::string base_what = "robot '" + name_ + "' base transform";
  const std::string tool_what = "robot '" + name_ + "' tool transform";
  check_pose(T_base_dh0_, base_what.c_str());
  check_pose(T_flange_tcp_, tool_what.c_str());
  T_dh0_base_ = T_base_dh0_.inverse(Eigen::Isometry);
  T_tcp_flange_ = T_flange_tcp_.inverse(Eigen::Isometry);
  plain_ = is_identity(T_base_dh0_) && is_identity(T_flange_tcp_);
  family_ = detect_family(rows_);
}

SerialChain& SerialChain::keep_extras_of(const SerialChain& other) {
  couplings_ = other.couplings_;
  variable_limits_ = other.variable_limits_;
  urdf_base_link_ = other.urdf_base_link_;
  urdf_tip_link_ = other.urdf_tip_link_;
  if (coupled()) family_ = ChainFamily::kGeneric;
  return *this;
}

SerialChain SerialChain::with_tool(const Eigen::Isometry3d& T_flange_tcp) const {
  return SerialChain(name_, rows_, limits_, T_base_dh0_, T_flange_tcp).keep_extras_of(*this);
}

SerialChain SerialChain::with_base(const Eigen::Isometry3d& T_base_dh0) const {
  return SerialChain(name_, rows_, limits_, T_base_dh0, T_flange_tcp_).keep_extras_of(*this);
}

SerialChain SerialChain::with_name(std::string name) const {
  return SerialChain(std::move(name), rows_, limits_, T_base_dh0_, T_flange_tcp_)
      .keep_extras_of(*this);
}

SerialChain SerialChain::with_urdf_links(std::string base_link, std::string tip_link) const {
  SerialChain out = *this;
  out.urdf_base_link_ = std::move(base_link);
  out.urdf_tip_link_ = std::move(tip_link);
  return out;
}

SerialChain SerialChain::uncoupled() const {
  SerialChain out = *this;
  out.couplings_ = {};
  out.variable_limits_.clear();
  out.family_ = detect_family(rows_);
  return out;
}

SerialChain SerialChain::with_couplings(JointCouplings couplings) const {
  const std::size_t n_variables = couplings.variables.size();
  VRREG_THROW_UNLESS(couplings.rows.size() == rows_.size(),
                     "robot '" << name_ << "': " << couplings.rows.size() << " couplings for "
                               << rows_.size() << " DH rows");
  VRREG_THROW_UNLESS(n_variables >= 1 && n_variables <= rows_.size(),
                     "robot '" << name_ << "': " << n_variables << " joint variables for "
                               << rows_.size() << " DH rows");
  std::vector<JointLimits> range(n_variables);
  std::vector<bool> followed(n_variables, false);
  for (std::size_t v = 0; v < n_variables; ++v) {
    const JointVariable& var = couplings.variables[v];
    const JointLimits& l = var.limits;
    VRREG_THROW_UNLESS(
        std::isfinite(l.lower_rad) && std::isfinite(l.upper_rad) && l.lower_rad < l.upper_rad,
        "robot '" << name_ << "': joint '" << var.name
                  << "' limits must be finite with lower < upper, got [" << l.lower_rad << ", "
                  << l.upper_rad << "]");
    range[v] = l;
  }
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const JointCoupling& c = couplings.rows[r];
    VRREG_THROW_UNLESS(c.variable >= 0 && static_cast<std::size_t>(c.variable) < n_variables,
                       "robot '" << name_ << "': DH row " << r + 1 << " follows joint variable "
                                 << c.variable + 1 << " of " << n_variables);
    const auto v = static_cast<std::size_t>(c.variable);
    const std::string& source = couplings.variables[v].name;
    VRREG_THROW_UNLESS(
        std::isfinite(c.multiplier) && c.multiplier != 0.0 && std::isfinite(c.offset),
        "robot '" << name_ << "': DH row " << r + 1 << " follows joint '" << source
                  << "' with multiplier " << c.multiplier << " and offset " << c.offset
                  << " (a finite, non-zero multiplier and a finite "
                  << "offset)");
    followed[v] = true;
    // The row's own limits as a range of the variable: q = (q_row - offset) / multiplier.
    double lo = (limits_[r].lower_rad - c.offset) / c.multiplier;
    double hi = (limits_[r].upper_rad - c.offset) / c.multiplier;
    if (lo > hi) std::swap(lo, hi);
    range[v].lower_rad = std::max(range[v].lower_rad, lo);
    range[v].upper_rad = std::min(range[v].upper_rad, hi);
  }
  for (std::size_t v = 0; v < n_variables; ++v) {
    const std::string& source = couplings.variables[v].name;
    VRREG_THROW_UNLESS(followed[v],
                       "robot '" << name_ << "': no DH row follows joint '" << source << "'");
    VRREG_THROW_UNLESS(range[v].lower_rad < range[v].upper_rad,
                       "robot '" << name_ << "': the limits of joint '" << source
                                 << "' and of the joints that follow it leave no common range");
  }
  SerialChain out = *this;
  out.couplings_ = std::move(couplings);
  out.variable_limits_ = std::move(range);
  out.family_ = ChainFamily::kGeneric;  // the analytic IKs solve for one variable per row
  return out;
}

bool SerialChain::prismatic(int i) const {
  return coupled() ? couplings_.variables[static_cast<std::size_t>(i)].type == JointType::kPrismatic
                   : row(i).prismatic();
}

bool SerialChain::wraps(int i) const {
  if (prismatic(i)) return false;
  if (!coupled()) return true;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const JointCoupling& c = couplings_.rows[r];
    if (c.variable != i) continue;
    if (rows_[r].prismatic() || c.multiplier != std::round(c.multiplier)) return false;
  }
  return true;
}

JointVector SerialChain::row_values(const JointRef& q) const {
  check_joints(q, "joint values");
  if (!coupled()) return q;
  JointVector out(n_rows());
  for (int r = 0; r < n_rows(); ++r) {
    const JointCoupling& c = couplings_.rows[static_cast<std::size_t>(r)];
    out(r) = c.multiplier * q(c.variable) + c.offset;
  }
  return out;
}

Eigen::MatrixXd SerialChain::coupling_matrix() const {
  if (!coupled()) return Eigen::MatrixXd::Identity(n_rows(), n_rows());
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n_rows(), n_joints());
  for (int r = 0; r < n_rows(); ++r) {
    const JointCoupling& c = couplings_.rows[static_cast<std::size_t>(r)];
    m(r, c.variable) = c.multiplier;
  }
  return m;
}

Eigen::Isometry3d SerialChain::dh0_flange_from_base_tcp(const Eigen::Isometry3d& T_base_tcp) const {
  if (plain_) return T_base_tcp;
  return T_dh0_base_ * T_base_tcp * T_tcp_flange_;
}

bool SerialChain::within_limits(const JointRef& q_rad, double tolerance_rad) const {
  if (q_rad.size() != n_joints()) return false;
  for (int i = 0; i < n_joints(); ++i) {
    const JointLimits& l = limit(i);
    if (!(q_rad(i) >= l.lower_rad - tolerance_rad && q_rad(i) <= l.upper_rad + tolerance_rad)) {
      return false;
    }
  }
  return true;
}

void SerialChain::check_joints(const JointRef& q_rad, const char* what) const {
  VRREG_THROW_UNLESS(q_rad.size() == n_joints(), what << ": robot '" << name_ << "' has "
                                                      << n_joints() << " joints, got "
                                                      << q_rad.size() << " joint values");
  for (Eigen::Index i = 0; i < q_rad.size(); ++i) {
    VRREG_THROW_UNLESS(std::isfinite(q_rad(i)),
                       what << ": joint " << i + 1 << " is not finite (" << q_rad(i) << ")");
  }
}

}  // namespace vrreg::kinematics
