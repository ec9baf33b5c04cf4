// SPDX-License-Identifier: Apache-2.0
// Numerical IK (numeric_ik.hpp): Levenberg-Marquardt steps dq = J^T (J J^T + lambda I)^-1 e on the
// pose error e = [p* - p; log(R* R^T)] (base frame), lambda cut tenfold after a step that lowers
// |e| and raised tenfold after one that does not, joints clamped into their limits after every
// step. Near a solution lambda falls to nothing and the steps are Gauss-Newton's, which converge
// quadratically down to the rounding of FK.
#include "vrreg/kinematics/numeric_ik.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/pose.hpp"

namespace vrreg::kinematics {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

constexpr double kAngleTolerance = 1e-9;   // rad, for the DH structure of branch joints
constexpr double kLengthTolerance = 1e-9;  // m
// Stall test of one start: every 25 steps, give up when |e|^2 is still above (1 mm)^2 and fell
// by less than 10 % since the last check. Closer in, slow progress (a stretched arm, a joint
// against its limit) is still progress.
constexpr int kStallWindow = 25;
constexpr double kFarCost = 1e-6;
constexpr double kStallRatio = 0.9;
constexpr double kNearCost = 1e-12;  // |e|^2: within a micrometre (or microradian)

Vector6 pose_error(const Eigen::Isometry3d& target, const Eigen::Isometry3d& current) {
  Vector6 e;
  e.head<3>() = target.translation() - current.translation();
  const Eigen::AngleAxisd rotation(Eigen::Matrix3d(target.linear() * current.linear().transpose()));
  e.tail<3>() = rotation.angle() * rotation.axis();
  return e;
}

struct Limits {
  JointVector lower, upper;
};

Limits search_limits(const SerialChain& chain, bool apply) {
  Limits l{JointVector(chain.n_joints()), JointVector(chain.n_joints())};
  for (int i = 0; i < chain.n_joints(); ++i) {
    // A slide, or a turn whose rows do not come back after a full turn, keeps its limits always.
    const bool keep = apply || !chain.wraps(i);
    l.lower(i) = keep ? chain.limit(i).lower_rad : -std::numeric_limits<double>::infinity();
    l.upper(i) = keep ? chain.limit(i).upper_rad : std::numeric_limits<double>::infinity();
  }
  return l;
}

JointVector random_start(const SerialChain& chain, const Limits& limits, Random& rng) {
  JointVector q(chain.n_joints());
  for (int i = 0; i < chain.n_joints(); ++i) {
    const double lo = std::isfinite(limits.lower(i)) ? limits.lower(i) : -std::numbers::pi;
    const double hi = std::isfinite(limits.upper(i)) ? limits.upper(i) : std::numbers::pi;
    q(i) = rng.uniform(lo, hi);
  }
  return q;
}

struct Descent {
  JointVector q;
  bool converged = false;
  double position_m = 0.0;
  double rotation_rad = 0.0;
};

Descent descend(const SerialChain& chain, const Eigen::Isometry3d& target, JointVector q,
                const Limits& limits, const NumericIkOptions& options) {
  q = q.cwiseMax(limits.lower).cwiseMin(limits.upper);
  Vector6 e = pose_error(target, forward_kinematics(chain, q));
  double cost = e.squaredNorm();
  double lambda = 1e-2;
  double checkpoint_cost = cost;
  Descent d;
  for (int it = 0;; ++it) {
    d.position_m = e.head<3>().norm();
    d.rotation_rad = e.tail<3>().norm();
    if (d.position_m <= options.position_tolerance_m &&
        d.rotation_rad <= options.rotation_tolerance_rad) {
      d.converged = true;
      break;
    }
    // A start within a micrometre goes on for up to ten times the budget: on a stretched arm the
    // error falls only linearly.
    const int budget = cost < kNearCost ? 10 * options.max_iterations : options.max_iterations;
    if (it >= budget || lambda > 1e10) break;
    // Every kStallWindow steps: a start that is far off and has stopped gaining is in a local
    // minimum (or against a limit); the next random start is the better use of the time.
    if (it > 0 && it % kStallWindow == 0) {
      if (cost > kFarCost && cost > kStallRatio * checkpoint_cost) break;
      checkpoint_cost = cost;
    }
    const Jacobian j = jacobian(chain, q);
    Eigen::Matrix<double, 6, 6> a = j * j.transpose();
    a.diagonal().array() += lambda;
    const JointVector step = j.transpose() * a.ldlt().solve(e);
    const JointVector q_new = (q + step).cwiseMax(limits.lower).cwiseMin(limits.upper);
    const Vector6 e_new = pose_error(target, forward_kinematics(chain, q_new));
    const double cost_new = e_new.squaredNorm();
    if (cost_new < cost) {
      q = q_new;
      e = e_new;
      cost = cost_new;
      lambda = std::max(lambda * 0.1, 1e-15);
    } else {
      lambda *= 10.0;
    }
  }
  d.q = q;
  return d;
}

// Joint k turns about z_{k-1}: the axes of joints k-1 (z_{k-2}) and k+1 (z_k) make an angle that
// varies with theta_k; they can become parallel at theta_k = 0 or pi only if |alpha_{k-1}| and
// |alpha_k| match (mod pi) and neither is 0.
bool neighbours_align(const DhRow& before, const DhRow& row) {
  const double sb = std::sin(before.alpha_rad), sa = std::sin(row.alpha_rad);
  if (std::abs(sb) <= kAngleTolerance || std::abs(sa) <= kAngleTolerance) return false;
  return std::abs(std::cos(before.alpha_rad) * std::cos(row.alpha_rad)) + std::abs(sb * sa) >=
         1.0 - kAngleTolerance;
}

// A planar elbow: joint k's axis parallel to joint k-1's, links on both sides of it.
bool planar_elbow(const DhRow& before, const DhRow& row) {
  return std::abs(std::sin(before.alpha_rad)) <= kAngleTolerance &&
         std::abs(before.a_m) > kLengthTolerance && std::abs(row.a_m) > kLengthTolerance;
}

}  // namespace

void NumericIkOptions::validate() const {
  VRREG_THROW_UNLESS(max_starts >= 1 && max_starts <= 100000,
                     "numeric IK: max_starts must be in 1..100000, got " << max_starts);
  VRREG_THROW_UNLESS(patience >= 1, "numeric IK: patience must be >= 1, got " << patience);
  VRREG_THROW_UNLESS(max_solutions >= 1,
                     "numeric IK: max_solutions must be >= 1, got " << max_solutions);
  VRREG_THROW_UNLESS(max_iterations >= 1 && max_iterations <= 100000,
                     "numeric IK: max_iterations must be in 1..100000, got " << max_iterations);
  VRREG_THROW_UNLESS(std::isfinite(position_tolerance_m) && position_tolerance_m > 0.0,
                     "numeric IK: position_tolerance_m must be > 0, got " << position_tolerance_m);
  VRREG_THROW_UNLESS(
      std::isfinite(rotation_tolerance_rad) && rotation_tolerance_rad > 0.0,
      "numeric IK: rotation_tolerance_rad must be > 0, got " << rotation_tolerance_rad);
}

namespace {

// Bit k set: DH row k + 1 is a branch joint.
std::uint16_t branch_rows(const SerialChain& chain) {
  std::uint16_t mask = 0;
  for (int k = 1; k + 1 < chain.n_rows(); ++k) {
    const DhRow& before = chain.row(k - 1);
    const DhRow& row = chain.row(k);
    if (row.prismatic() || before.prismatic()) continue;
    if ((neighbours_align(before, row) && !chain.row(k + 1).prismatic()) ||
        planar_elbow(before, row)) {
      mask = static_cast<std::uint16_t>(mask | 1u << k);
    }
  }
  return mask;
}

// The joint variable DH row `k` follows (itself on an uncoupled chain).
int variable_of_row(const SerialChain& chain, int k) {
  return chain.coupled() ? chain.couplings().rows[static_cast<std::size_t>(k)].variable : k;
}

}  // namespace

std::uint16_t branch_joints(const SerialChain& chain) {
  const std::uint16_t rows = branch_rows(chain);
  std::uint16_t mask = 0;
  for (int k = 0; k < chain.n_rows(); ++k) {
    if ((rows >> k & 1) != 0)
      mask = static_cast<std::uint16_t>(mask | 1u << variable_of_row(chain, k));
  }
  return mask;
}

ConfigurationLabel generic_configuration(const SerialChain& chain, const JointRef& q_rad) {
  chain.check_joints(q_rad, "configuration");
  const JointVector q_row = chain.row_values(q_rad);
  const std::uint16_t rows = branch_rows(chain);
  // The sign of each branch row's sin(theta), on the bit of the variable it follows (the first
  // such row's where several rows follow one variable).
  std::uint16_t mask = 0;
  std::uint16_t negative = 0;
  for (int k = 0; k < chain.n_rows(); ++k) {
    if ((rows >> k & 1) == 0) continue;
    const auto bit = static_cast<std::uint16_t>(1u << variable_of_row(chain, k));
    if ((mask & bit) != 0) continue;
    mask = static_cast<std::uint16_t>(mask | bit);
    if (std::sin(q_row(k) + chain.row(k).theta_offset_rad) < 0.0) {
      negative = static_cast<std::uint16_t>(negative | bit);
    }
  }
  return ConfigurationLabel::generic(mask, negative);
}

IkResult numeric_inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                                    const NumericIkOptions& options,
                                    const std::optional<JointVector>& q_start_rad) {
  options.validate();
  check_pose(T_base_tcp, "numeric inverse kinematics: target pose");
  if (q_start_rad) chain.check_joints(*q_start_rad, "numeric inverse kinematics: start joints");
  const Limits limits = search_limits(chain, options.apply_joint_limits);
  Random rng(options.seed);
  std::map<int, IkSolution> found;  // by class index
  int stale = 0;
  double closest_m = std::numeric_limits<double>::infinity(), closest_rad = 0.0;
  int start = 0;
  for (; start < options.max_starts + (q_start_rad ? 1 : 0) && stale < options.patience &&
         static_cast<int>(found.size()) < options.max_solutions;
       ++start) {
    const JointVector q0 =
        start == 0 && q_start_rad ? *q_start_rad : random_start(chain, limits, rng);
    Descent d = descend(chain, T_base_tcp, q0, limits, options);
    if (!d.converged) {
      if (d.position_m < closest_m) {
        closest_m = d.position_m;
        closest_rad = d.rotation_rad;
      }
      continue;
    }
    if (!options.apply_joint_limits) {
      for (int i = 0; i < chain.n_joints(); ++i) {
        if (chain.wraps(i)) d.q(i) = wrap_angle(d.q(i));
      }
    }
    IkSolution solution;
    solution.q_rad = d.q;
    solution.config = generic_configuration(chain, d.q);
    const bool is_new = found.emplace(solution.config.index(), solution).second;
    stale = is_new ? 0 : stale + 1;
  }
  IkResult result;
  for (const auto& [index, solution] : found) result.solutions.push_back(solution);
  if (result.solutions.empty()) {
    result.status = IkStatus::kUnreachable;
    result.message = "none of " + std::to_string(start) +
                     " starts converged (closest: " + format_general(units::m_to_mm(closest_m), 4) +
                     " mm, " + format_general(units::rad_to_deg(closest_rad), 4) +
                     " deg away); the pose may be out of reach" +
                     (options.apply_joint_limits ? " within the joint limits" : "");
  } else {
    result.status = IkStatus::kOk;
  }
  return result;
}

}  // namespace vrreg::kinematics
