// SPDX-License-Identifier: Apache-2.0
#include "joint_rotation.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::detail {
namespace {

constexpr int kDegrees[] = {-1, 0, 1, 2, 4, 6, 8};
// Singular values kept, relative to the largest of the unit-norm columns: cross-validation picks
// one. A fixed tool orientation makes many link rotations and joint offsets nearly the same
// column; keeping their tiny singular values turns the orientation noise into rotations of
// radians that cancel only at the fiducials.
constexpr double kRelativeThresholds[] = {1e-9, 1e-6, 1e-4, 1e-3, 1e-2, 3e-2, 1e-1};
constexpr std::size_t kThresholds = std::size(kRelativeThresholds);
constexpr double kNearTie = 1.01;

// The periodic terms must lower the cross-validated RMS by this fraction to be kept (as the
// positions' joint model's); at most this many, each above a false-alarm rate of kFalseAlarm
// over all the frequencies tried (noise alone: drop / sigma^2 ~ chi^2 with 2 degrees of
// freedom per frequency).
constexpr double kPeriodicGain = 1e-3;
constexpr int kMaxPeriodicTerms = 12;
constexpr double kFalseAlarm = 1e-3;
// A residual below this RMS per component is rounding, in which a periodogram finds only noise.
constexpr double kRoundingRad = 1e-13;
// Gauss-Newton steps on the periodic terms' frequencies, and the relative change of the
// residual's sum of squares below which they stop.
constexpr int kFrequencySteps = 8;
constexpr double kFrequencyTolerance = 1e-12;

// The model's columns: n (degree + 1) joint-function columns, then 3 per link frame when the
// links' rotations are fitted, one per joint when the positions' joint-angle errors are scaled,
// two per periodic term, then (when fitting) 3 for a constant rotation, fitted jointly with the
// others and left to the mean residual afterwards.
Eigen::Index n_columns(const JointRotationTerms& m, int n_joints, bool links, bool constant,
                       bool scaled = false) {
  return n_joints * (m.degree + 1) + (links ? 3 * n_joints : 0) + (scaled ? n_joints : 0) +
         2 * std::ssize(m.periodic) + (constant ? 3 : 0);
}

// The design rows d g / d c of one fiducial (3 x n_columns).
void design_rows(const kinematics::SerialChain& chain, const JointRotationTerms& m, bool links,
                 bool constant, const Eigen::Ref<const Eigen::VectorXd>& q_rad,
                 const Eigen::VectorXd* dq_rad, Eigen::Ref<Eigen::MatrixXd> rows) {
  const kinematics::Jacobian J = kinematics::jacobian(chain, q_rad);
  const int per_joint = m.degree + 1;
  const Eigen::Index first_link = q_rad.size() * per_joint;
  if (links) {  // link i's rotation r_i, in its own frame: R_base_i(q) r_i
    const std::vector<Eigen::Isometry3d> frames = kinematics::link_frames(chain, q_rad);
    for (Eigen::Index i = 0; i < q_rad.size(); ++i) {
      rows.middleCols<3>(first_link + 3 * i) = frames[static_cast<std::size_t>(i) + 1].linear();
    }
  }
  const Eigen::Index first_scaled = first_link + (links ? 3 * q_rad.size() : 0);
  if (dq_rad != nullptr) {  // the positions' joint-angle error of each joint, along its axis
    for (Eigen::Index i = 0; i < q_rad.size(); ++i) {
      rows.col(first_scaled + i) = J.block<3, 1>(3, i) * (*dq_rad)(i);
    }
  }
  const Eigen::Index first_periodic = first_scaled + (dq_rad != nullptr ? q_rad.size() : 0);
  for (std::size_t t = 0; t < m.periodic.size(); ++t) {  // joint i's sin and cos along its axis
    const kinematics::JointPeriodicTerm& term = m.periodic[t];
    const double w_q = term.omega_per_rad * q_rad(term.joint);
    const Eigen::Index c = first_periodic + 2 * static_cast<Eigen::Index>(t);
    rows.col(c) = J.block<3, 1>(3, term.joint) * std::sin(w_q);
    rows.col(c + 1) = J.block<3, 1>(3, term.joint) * std::cos(w_q);
  }
  if (constant) rows.rightCols<3>().setIdentity();
  for (Eigen::Index i = 0; i < q_rad.size(); ++i) {
    const double span = m.q_hi_rad(i) - m.q_lo_rad(i);
    const double u =
        span > 0.0 ? std::clamp(2.0 * (q_rad(i) - m.q_lo_rad(i)) / span - 1.0, -1.0, 1.0) : 0.0;
    double p_prev = 1.0;  // Legendre P_0, P_1, ... by the three-term recurrence
    double p = u;
    for (int k = 0; k < per_joint; ++k) {
      double value = 1.0;
      if (k == 1) value = u;
      if (k >= 2) {
        const double next = ((2.0 * k - 1.0) * u * p - (k - 1.0) * p_prev) / k;
        p_prev = p;
        p = next;
        value = next;
      }
      rows.col(i * per_joint + k) = J.block<3, 1>(3, i) * value;
    }
  }
}

Eigen::MatrixXd design(const kinematics::SerialChain& chain, const JointRotationTerms& m,
                       bool links, const Eigen::MatrixXd& joints_rad, const Eigen::MatrixXd* dq_rad,
                       const std::vector<Eigen::Index>& which) {
  Eigen::MatrixXd a(
      3 * static_cast<Eigen::Index>(which.size()),
      n_columns(m, static_cast<int>(joints_rad.rows()), links, true, dq_rad != nullptr));
  for (std::size_t r = 0; r < which.size(); ++r) {
    const Eigen::VectorXd dq =
        dq_rad != nullptr ? Eigen::VectorXd(dq_rad->col(which[r])) : Eigen::VectorXd();
    design_rows(chain, m, links, true, joints_rad.col(which[r]), dq_rad != nullptr ? &dq : nullptr,
                a.middleRows(3 * static_cast<Eigen::Index>(r), 3));
  }
  return a;
}

// The fitted coefficients into the terms: joint functions, the links' rotations, the constant.
void store(JointRotationTerms& m, bool links, bool scaled, const Eigen::VectorXd& c, int n_joints) {
  const Eigen::Index joint_columns = n_joints * (m.degree + 1);
  m.coefficients = c.head(joint_columns);
  m.link_rotations_rad =
      links ? Eigen::VectorXd(c.segment(joint_columns, 3 * n_joints)) : Eigen::VectorXd();
  const Eigen::Index first_scaled = joint_columns + (links ? 3 * n_joints : 0);
  m.position_joint_scales =
      scaled ? Eigen::VectorXd(c.segment(first_scaled, n_joints)) : Eigen::VectorXd();
  m.periodic_coefficients =
      c.segment(first_scaled + (scaled ? n_joints : 0), 2 * std::ssize(m.periodic));
  m.constant_rad = c.tail<3>();
}

Eigen::VectorXd coefficients_of(const JointRotationTerms& m) {
  Eigen::VectorXd c(m.coefficients.size() + m.link_rotations_rad.size() +
                    m.position_joint_scales.size() + m.periodic_coefficients.size());
  c << m.coefficients, m.link_rotations_rad, m.position_joint_scales, m.periodic_coefficients;
  return c;
}

Eigen::VectorXd targets(const Points3& g, const std::vector<Eigen::Index>& which) {
  Eigen::VectorXd b(3 * static_cast<Eigen::Index>(which.size()));
  for (std::size_t r = 0; r < which.size(); ++r)
    b.segment<3>(3 * static_cast<Eigen::Index>(r)) = g.col(which[r]);
  return b;
}

// Least squares on unit-norm columns, minimum norm by SVD, once per design; solution() gives
// the coefficients that keep the singular values above a relative threshold. Jacobi, not
// divide-and-conquer: Eigen 3.4's BDCSVD crashed on some of these designs (a fixed tool
// orientation's exactly repeated columns).
class TruncatedSvd {
 public:
  TruncatedSvd(const Eigen::MatrixXd& a, const Eigen::VectorXd& b)
      : scale_(Eigen::VectorXd::Zero(a.cols())) {
    for (Eigen::Index c = 0; c < a.cols(); ++c) {
      const double norm = a.col(c).norm();
      scale_(c) = norm > 0.0 ? 1.0 / norm : 0.0;
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a * scale_.asDiagonal(),
                                                Eigen::ComputeThinU | Eigen::ComputeThinV);
    s_ = svd.singularValues();
    v_ = svd.matrixV();
    ub_ = svd.matrixU().transpose() * b;
  }
  [[nodiscard]] Eigen::VectorXd solution(double relative_threshold) const {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(s_.size());
    const double largest = s_.size() > 0 ? s_(0) : 0.0;
    for (Eigen::Index i = 0; i < s_.size(); ++i) {
      if (s_(i) > relative_threshold * largest && s_(i) > 0.0) y(i) = ub_(i) / s_(i);
    }
    return scale_.asDiagonal() * (v_ * y);
  }
  [[nodiscard]] int rank(double relative_threshold) const {
    const double largest = s_.size() > 0 ? s_(0) : 0.0;
    return static_cast<int>((s_.array() > relative_threshold * largest).count());
  }

 private:
  Eigen::VectorXd scale_;
  Eigen::VectorXd s_{};
  Eigen::MatrixXd v_{};
  Eigen::VectorXd ub_{};
};

// What fit_joint_rotation fits, and its folds' order.
struct Problem {
  const kinematics::SerialChain& chain;
  const Eigen::MatrixXd& joints_rad;
  const Points3& g_robot_rad;
  const Eigen::MatrixXd* dq_rad;
  int folds;
  const std::vector<Eigen::Index>& order;
};

// The fit of `m`'s columns to the residuals at every fiducial: the design, its coefficients,
// what it leaves (3 per fiducial) and the combinations kept.
struct FullFit {
  Eigen::MatrixXd a;
  Eigen::VectorXd x;
  Eigen::VectorXd left;
  int rank = 0;
};

FullFit fit_all(const Problem& p, const JointRotationTerms& m, bool links, double threshold) {
  std::vector<Eigen::Index> all(static_cast<std::size_t>(p.g_robot_rad.cols()));
  std::iota(all.begin(), all.end(), Eigen::Index{0});
  FullFit out;
  out.a = design(p.chain, m, links, p.joints_rad, p.dq_rad, all);
  const Eigen::VectorXd b = targets(p.g_robot_rad, all);
  const TruncatedSvd svd(out.a, b);
  out.x = svd.solution(threshold);
  out.left = b - out.a * out.x;
  out.rank = svd.rank(threshold);
  return out;
}

// Gauss-Newton on the periodic terms' frequencies, every coefficient fitted with them: the
// periodogram's peak is that of what the terms before it left, off where terms overlap (and
// on a grid). A term's derivative in its frequency w is z_i q_i (s cos(w q_i) - c sin(w q_i)),
// from its own two columns. A step is kept only where it lowers the residual.
void refine_frequencies(const Problem& p, JointRotationTerms& m, bool links, double threshold) {
  const Eigen::Index n = p.g_robot_rad.cols();
  const auto n_terms = std::ssize(m.periodic);
  FullFit fit = fit_all(p, m, links, threshold);
  for (int step = 0; step < kFrequencySteps && n_terms > 0; ++step) {
    // The periodic columns sit just before the constant's three.
    const Eigen::Index first = fit.a.cols() - 3 - 2 * n_terms;
    Eigen::MatrixXd a(fit.a.rows(), fit.a.cols() + n_terms);
    a.leftCols(fit.a.cols()) = fit.a;
    for (Eigen::Index t = 0; t < n_terms; ++t) {
      const int joint = m.periodic[static_cast<std::size_t>(t)].joint;
      const double s = fit.x(first + 2 * t);
      const double c = fit.x(first + 2 * t + 1);
      for (Eigen::Index j = 0; j < n; ++j) {
        a.block<3, 1>(3 * j, fit.a.cols() + t) =
            p.joints_rad(joint, j) * (s * fit.a.block<3, 1>(3 * j, first + 2 * t + 1) -
                                      c * fit.a.block<3, 1>(3 * j, first + 2 * t));
      }
    }
    const Eigen::VectorXd dw =
        TruncatedSvd(a, fit.a * fit.x + fit.left).solution(threshold).tail(n_terms);
    JointRotationTerms trial = m;
    for (Eigen::Index t = 0; t < n_terms; ++t) {
      trial.periodic[static_cast<std::size_t>(t)].omega_per_rad += dw(t);
      if (!(trial.periodic[static_cast<std::size_t>(t)].omega_per_rad > 0.0)) return;
    }
    FullFit next = fit_all(p, trial, links, threshold);
    const double rss = fit.left.squaredNorm();
    const double next_rss = next.left.squaredNorm();
    if (!(next_rss < rss)) return;
    const bool converged = rss - next_rss <= kFrequencyTolerance * rss;
    m = std::move(trial);
    fit = std::move(next);
    if (converged) return;
  }
}

// A cross-validated choice: the terms' layout (degree, ranges, periodic terms), whether the
// links' rotations enter, the singular values kept, and the folds' RMS.
struct Choice {
  JointRotationTerms terms{};
  bool links = false;
  double threshold = 0.0;
  double rms_rad = 0.0;
};

// The degree among kDegrees, the links' rotations or not and the singular values kept, by the
// folds' RMS, for the periodic terms of `layout` (and its ranges).
Choice choose(const Problem& p, const JointRotationTerms& layout) {
  const Eigen::Index n = p.g_robot_rad.cols();
  const int n_joints = p.chain.n_joints();
  JointRotationTerms m = layout;
  struct Candidate {
    double rms_rad;
    int degree;
    bool links;
    std::size_t threshold;
    Eigen::Index columns;
  };
  std::vector<Candidate> candidates;
  for (const bool links : {false, true}) {
    for (const int degree : kDegrees) {
      m.degree = degree;
      const Eigen::Index columns = n_columns(m, n_joints, links, true, p.dq_rad != nullptr);
      // At least four equations a column: on fewer (27 fiducials and 33 columns) the folds'
      // RMS, the best of a hundred candidates, promised a third of what targets then got.
      if (3 * n < 4 * columns) break;
      std::array<double, kThresholds> sum_sq{};
      for (int fold = 0; fold < p.folds; ++fold) {
        std::vector<Eigen::Index> train, test;
        for (std::size_t r = 0; r < p.order.size(); ++r)
          (static_cast<int>(r % static_cast<std::size_t>(p.folds)) == fold ? test : train)
              .push_back(p.order[r]);
        const TruncatedSvd svd(design(p.chain, m, links, p.joints_rad, p.dq_rad, train),
                               targets(p.g_robot_rad, train));
        const Eigen::MatrixXd a_test = design(p.chain, m, links, p.joints_rad, p.dq_rad, test);
        const Eigen::VectorXd b_test = targets(p.g_robot_rad, test);
        for (std::size_t t = 0; t < kThresholds; ++t) {
          sum_sq[t] += (a_test * svd.solution(kRelativeThresholds[t]) - b_test).squaredNorm();
        }
      }
      for (std::size_t t = 0; t < kThresholds; ++t) {
        candidates.push_back(
            {std::sqrt(sum_sq[t] / static_cast<double>(n)), degree, links, t, columns});
      }
    }
  }
  // The simplest model within 1 % of the best cross-validated RMS: the most singular values
  // dropped, then the fewest columns. Near-ties otherwise go to combinations kept at tiny
  // singular values, which cancel to radians at the fiducials and nowhere else.
  double best_rms = std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates) best_rms = std::min(best_rms, c.rms_rad);
  const Candidate* chosen = nullptr;
  for (const Candidate& c : candidates) {
    if (c.rms_rad > kNearTie * best_rms) continue;
    if (chosen == nullptr || c.threshold > chosen->threshold ||
        (c.threshold == chosen->threshold && c.columns < chosen->columns)) {
      chosen = &c;
    }
  }
  VRREG_THROW_UNLESS(chosen != nullptr, "joint rotation: " << n << " fiducials are too few");
  m.degree = chosen->degree;
  return {std::move(m), chosen->links, kRelativeThresholds[chosen->threshold], chosen->rms_rad};
}

}  // namespace

void validate_joint_rotation(const JointRotationTerms& t, int n_joints) {
  VRREG_THROW_UNLESS(t.degree >= -1 && t.degree <= 40, "joint rotation: degree " << t.degree);
  VRREG_THROW_UNLESS(t.constant_rad.allFinite(), "joint rotation: the constant is not finite");
  VRREG_THROW_UNLESS(
      (t.link_rotations_rad.size() == 0 || t.link_rotations_rad.size() == 3 * n_joints) &&
          t.link_rotations_rad.allFinite() &&
          (t.position_joint_scales.size() == 0 || t.position_joint_scales.size() == n_joints) &&
          t.position_joint_scales.allFinite(),
      "joint rotation: link rotations or joint scales do not fit " << n_joints << " joints");
  VRREG_THROW_UNLESS(t.periodic_coefficients.size() == 2 * std::ssize(t.periodic) &&
                         t.periodic_coefficients.allFinite(),
                     "joint rotation: " << t.periodic_coefficients.size()
                                        << " periodic coefficients for " << t.periodic.size()
                                        << " periodic terms");
  for (const kinematics::JointPeriodicTerm& p : t.periodic) {
    VRREG_THROW_UNLESS(p.joint >= 0 && p.joint < n_joints && std::isfinite(p.omega_per_rad) &&
                           p.omega_per_rad > 0.0,
                       "joint rotation: a periodic term of joint "
                           << p.joint + 1 << " (of " << n_joints << ") at " << p.omega_per_rad
                           << " / rad");
  }
  if (t.degree < 0) {
    VRREG_THROW_UNLESS(t.coefficients.size() == 0, "joint rotation: coefficients without a degree");
    return;
  }
  VRREG_THROW_UNLESS(t.q_lo_rad.size() == n_joints && t.q_hi_rad.size() == n_joints &&
                         t.coefficients.size() == n_joints * (t.degree + 1) &&
                         t.q_lo_rad.allFinite() && t.q_hi_rad.allFinite() &&
                         t.coefficients.allFinite(),
                     "joint rotation: sizes or values do not fit " << n_joints << " joints");
}

Eigen::Vector3d joint_rotation_rad(const JointRotationTerms& terms,
                                   const kinematics::SerialChain& chain,
                                   const Eigen::Ref<const Eigen::VectorXd>& q_rad,
                                   const Eigen::VectorXd* dq_rad) {
  const bool links = terms.link_rotations_rad.size() > 0;
  const bool scaled = terms.position_joint_scales.size() > 0;
  if (terms.degree < 0 && !links && !scaled && terms.periodic.empty()) return terms.constant_rad;
  VRREG_THROW_UNLESS(!scaled || (dq_rad != nullptr && dq_rad->size() == q_rad.size()),
                     "joint rotation: the positions' joint-angle errors are needed");
  Eigen::MatrixXd rows(3, n_columns(terms, chain.n_joints(), links, false, scaled));
  design_rows(chain, terms, links, false, q_rad, scaled ? dq_rad : nullptr, rows);
  return rows * coefficients_of(terms) + terms.constant_rad;
}

JointRotationFit fit_joint_rotation(const kinematics::SerialChain& chain,
                                    const Eigen::MatrixXd& joints_rad, const Points3& g_robot_rad,
                                    const Eigen::MatrixXd* dq_rad, int folds, std::uint64_t seed) {
  const Eigen::Index n = g_robot_rad.cols();
  VRREG_THROW_UNLESS(joints_rad.cols() == n && joints_rad.rows() == chain.n_joints() && folds >= 2,
                     "joint rotation: " << joints_rad.rows() << " x " << joints_rad.cols()
                                        << " joints for " << n << " residuals");
  JointRotationTerms ranges;
  ranges.q_lo_rad = joints_rad.rowwise().minCoeff();
  ranges.q_hi_rad = joints_rad.rowwise().maxCoeff();
  // Folds from a seeded shuffle: the same fiducials, the same choice.
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  Random rng(seed);
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  const Problem problem{chain, joints_rad, g_robot_rad, dq_rad, folds, order};
  Choice best = choose(problem, ranges);
  // Cyclic joint-angle errors, greedily, each the periodogram's peak of what the choice with the
  // terms so far leaves, while the peak is above what noise alone would give.
  JointRotationTerms search = best.terms;
  while (std::ssize(search.periodic) < kMaxPeriodicTerms) {
    const FullFit fit = fit_all(problem, search, best.links, best.threshold);
    const Eigen::Index dof = 3 * n - fit.rank;
    if (dof <= 0) break;
    const double sigma2 = fit.left.squaredNorm() / static_cast<double>(dof);
    if (!(sigma2 > kRoundingRad * kRoundingRad)) break;
    const PeriodicPeak peak =
        strongest_periodic_term(chain, joints_rad, Points3(fit.left.reshaped(3, n)));
    const double threshold = 2.0 * std::log(std::max(1, peak.n_candidates) / kFalseAlarm);
    if (peak.joint < 0 || !(peak.drop > threshold * sigma2)) break;
    search.periodic.push_back({peak.joint, peak.omega_per_rad});
    refine_frequencies(problem, search, best.links, best.threshold);
  }
  if (!search.periodic.empty()) {
    ranges.periodic = search.periodic;
    Choice with = choose(problem, ranges);
    if (with.rms_rad < best.rms_rad * (1.0 - kPeriodicGain)) best = std::move(with);
  }
  const FullFit fit = fit_all(problem, best.terms, best.links, best.threshold);
  JointRotationFit out;
  out.cv_rms_rad = best.rms_rad;
  out.columns = static_cast<int>(fit.a.cols());
  out.rank = fit.rank;
  out.terms = std::move(best.terms);
  store(out.terms, best.links, dq_rad != nullptr, fit.x, chain.n_joints());
  if (out.terms.degree < 0) out.terms.coefficients.resize(0);
  return out;
}

}  // namespace vrreg::detail
