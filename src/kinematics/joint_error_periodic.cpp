// SPDX-License-Identifier: Apache-2.0
// Periodic joint-angle error terms of the joint-space error model, found from the fiducials: a
// greedy periodogram (least squares on a sine and a cosine, as Lomb-Scargle) of what a smooth
// model leaves. A transmission's cyclic error (gear mesh, harmonic drive) has a period far
// shorter than the joint's travel: a Legendre series needs ~2 degrees per period for it, and
// between sparse samples of the joint angle (a grid's columns share q1) such a polynomial is
// free, while a sinusoid of the right frequency is pinned down by a few irregular samples.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "joint_error_solve.hpp"

namespace vrreg::kinematics {
namespace {

// The smooth model the periodogram searches beyond: Legendre degree per joint (at most the
// degree choice's cap), with DH, marker, trend and the terms so far.
constexpr int kSmoothDegree = 4;
// Frequency grid step: the phase of a candidate moves by 2 pi / kOversampling over the range, a
// quarter of a peak's main lobe (the golden-section search then finds its top).
constexpr int kOversampling = 4;
// At most this many frequencies per joint: periods down to range / 512; shorter ones are not
// searched on a densely sampled joint.
constexpr int kMaxCandidates = 2048;
// Chance that noise alone would pass the acceptance test anywhere on the whole grid.
constexpr double kFalseAlarm = 1e-3;
// A joint sampled at fewer distinct angles is not searched: a sinusoid has 3 unknowns.
constexpr int kMinDistinctAngles = 8;
// Golden-section steps refining the best grid frequency within one grid step (bracket 2 step x
// 0.618^24 < step / 4096), and the frequency's resolution after it: rounded to step / 4096, far
// finer than its statistical uncertainty, so that inputs equal to the last digits (a model read
// back from its JSON file) give the same frequency, not the last steps of the search's
// comparisons flipped.
constexpr int kRefineSteps = 24;
constexpr double kFrequencyResolution = 1.0 / 4096.0;
// The periodic terms must lower the CV RMS by this fraction to be kept (as a higher degree).
constexpr double kPeriodicGain = 1e-3;

// The smooth model's design at x = 0 without periodic terms, built once (it needs the forward
// kinematics of every fiducial); a term's columns are a joint's column times sin and cos.
struct SmoothDesign {
  Eigen::MatrixXd base;           // 3 J x the smooth layout's columns
  std::vector<int> joint_column;  // each joint's degree-0 column: its Jacobian column
};

SmoothDesign smooth_design(const JointErrorModel::State& s, const std::vector<JointVector>& q_rad,
                           const std::vector<int>& distinct) {
  JointErrorModel::State t = s;
  t.layout.degrees.clear();
  for (const int d : distinct)
    t.layout.degrees.push_back(std::min(kSmoothDegree, joint_degree_cap(d)));
  t.layout.periodic.clear();
  SmoothDesign out;
  for (int i = 0; i < t.layout.n_joints(); ++i)
    out.joint_column.push_back(t.layout.joint_column(i));
  out.base = design_matrix(t, Eigen::VectorXd::Zero(t.layout.n_columns()), q_rad);
  return out;
}

struct SmoothFit {
  Eigen::VectorXd residual;  // e - A x
  double sigma2 = 0.0;       // |residual|^2 / (3 J - rank)
  bool ok = false;
};

// The smooth model with `terms` (design_rows' columns for them: periodic_factors times the
// joint's column, appended last).
SmoothFit fit_smooth(const SmoothDesign& d, const std::vector<JointVector>& q_rad,
                     const Eigen::VectorXd& e, const JointErrorModelOptions& options,
                     const std::vector<JointPeriodicTerm>& terms) {
  const Eigen::Index n_base = d.base.cols();
  Eigen::MatrixXd a(d.base.rows(), n_base + 2 * static_cast<Eigen::Index>(terms.size()));
  a.leftCols(n_base) = d.base;
  for (std::size_t m = 0; m < terms.size(); ++m) {
    const Eigen::Index c = n_base + 2 * static_cast<Eigen::Index>(m);
    const int column = d.joint_column[static_cast<std::size_t>(terms[m].joint)];
    for (std::size_t j = 0; j < q_rad.size(); ++j) {
      const auto r = static_cast<Eigen::Index>(3 * j);
      const auto [sin_w, cos_w] = periodic_factors(terms[m], q_rad[j](terms[m].joint));
      a.block<3, 1>(r, c) = d.base.block<3, 1>(r, column) * sin_w;
      a.block<3, 1>(r, c + 1) = d.base.block<3, 1>(r, column) * cos_w;
    }
  }
  SmoothFit out;
  const std::vector<Eigen::Index> cols = independent_columns(a, options.relative_rank_tolerance);
  const auto dof = e.size() - static_cast<Eigen::Index>(cols.size());
  if (dof <= 0) return out;
  out.residual = e - a * solve_columns(a, cols, e);
  out.sigma2 = out.residual.squaredNorm() / static_cast<double>(dof);
  out.ok = out.sigma2 > 0.0;
  return out;
}

// Per fiducial: g_j . r_j and |g_j|^2 of the joint's Jacobian column g and the residual r.
struct JointSums {
  std::vector<double> q;   // the joint's angle [rad]
  std::vector<double> gr;  // g_j . r_j
  std::vector<double> gg;  // |g_j|^2
};

// Sums over the fiducials for one frequency: with A = g sin(w q), B = g cos(w q) stacked, A.r,
// B.r, A.A, B.B and A.B.
struct PairSums {
  double ar = 0.0, br = 0.0, aa = 0.0, bb = 0.0, ab = 0.0;

  void add(double gr, double gg, double u, double v) {
    ar += gr * u;
    br += gr * v;
    aa += gg * u * u;
    bb += gg * v * v;
    ab += gg * u * v;
  }
  // The drop of |r|^2 by a least-squares fit of r on A and B (0 when they are nearly one).
  [[nodiscard]] double drop() const {
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-12 * aa * bb)) return 0.0;
    return (bb * ar * ar - 2.0 * ab * ar * br + aa * br * br) / det;
  }
};

double drop(const JointSums& j, double omega) {
  PairSums sums;
  for (std::size_t k = 0; k < j.q.size(); ++k) {
    sums.add(j.gr[k], j.gg[k], std::sin(omega * j.q[k]), std::cos(omega * j.q[k]));
  }
  return sums.drop();
}

struct Peak {
  double drop = 0.0;
  double omega = 0.0;
};

// The grid's highest peak, sines and cosines stepped by rotation (exact again every 256 steps).
Peak scan(const JointSums& j, double omega_lo, double step, int n_steps) {
  const std::size_t n = j.q.size();
  std::vector<double> s(n), c(n), ds(n), dc(n);
  Peak best;
  for (int k = 0; k < n_steps; ++k) {
    const double omega = omega_lo + k * step;
    if (k % 256 == 0) {
      for (std::size_t m = 0; m < n; ++m) {
        s[m] = std::sin(omega * j.q[m]);
        c[m] = std::cos(omega * j.q[m]);
        ds[m] = std::sin(step * j.q[m]);
        dc[m] = std::cos(step * j.q[m]);
      }
    }
    PairSums sums;
    for (std::size_t m = 0; m < n; ++m) {
      sums.add(j.gr[m], j.gg[m], s[m], c[m]);
      const double s_next = s[m] * dc[m] + c[m] * ds[m];
      c[m] = c[m] * dc[m] - s[m] * ds[m];
      s[m] = s_next;
    }
    const double d = sums.drop();
    if (d > best.drop) best = {d, omega};
  }
  return best;
}

// Golden-section search for the highest drop within one grid step of `omega`.
Peak refine(const JointSums& j, Peak peak, double step) {
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = peak.omega - step, hi = peak.omega + step;
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = drop(j, x1), f2 = drop(j, x2);
  for (int it = 0; it < kRefineSteps; ++it) {
    if (f1 > f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = drop(j, x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = drop(j, x2);
    }
  }
  const double quantum = kFrequencyResolution * step;
  const double omega = quantum * std::round((f1 > f2 ? x1 : x2) / quantum);
  const double d = drop(j, omega);
  return d > peak.drop ? Peak{d, omega} : peak;
}

}  // namespace

std::vector<JointPeriodicTerm> find_periodic_terms(const JointErrorModel::State& s,
                                                   const std::vector<JointVector>& q_rad,
                                                   const ConstPoints3Ref& error_robot_m,
                                                   const JointErrorModelOptions& options) {
  const int n_joints = s.nominal.n_joints();
  const auto n_fid = q_rad.size();
  const Points3 e_points = error_robot_m;
  const Eigen::Map<const Eigen::VectorXd> e(e_points.data(), 3 * e_points.cols());
  std::vector<int> distinct;
  for (int i = 0; i < n_joints; ++i) distinct.push_back(distinct_joint_values(q_rad, i));
  const SmoothDesign design = smooth_design(s, q_rad, distinct);
  std::vector<JointPeriodicTerm> terms;
  while (static_cast<int>(terms.size()) < options.max_periodic_terms) {
    const SmoothFit fit = fit_smooth(design, q_rad, e, options, terms);
    if (!fit.ok) break;
    Peak best;
    int best_joint = -1;
    int n_candidates = 0;
    for (int i = 0; i < n_joints; ++i) {
      const double range = s.q_hi_rad(i) - s.q_lo_rad(i);
      const int n_angles = distinct[static_cast<std::size_t>(i)];
      if (!(range > 0.0) || n_angles < kMinDistinctAngles) continue;
      // From one period over the range to the mean Nyquist rate of the distinct angles.
      const double step = 2.0 * std::numbers::pi / (kOversampling * range);
      const double omega_lo = 2.0 * std::numbers::pi / range;
      const double omega_hi = std::numbers::pi * (n_angles - 1) / range;
      const int n_steps =
          std::min(kMaxCandidates, static_cast<int>((omega_hi - omega_lo) / step) + 1);
      if (n_steps < 1) continue;
      JointSums sums;
      const int column = design.joint_column[static_cast<std::size_t>(i)];
      for (std::size_t j = 0; j < n_fid; ++j) {
        const auto r = static_cast<Eigen::Index>(3 * j);
        const Eigen::Vector3d g = design.base.block<3, 1>(r, column);
        sums.q.push_back(q_rad[j](i));
        sums.gr.push_back(g.dot(fit.residual.segment<3>(r)));
        sums.gg.push_back(g.squaredNorm());
      }
      n_candidates += n_steps;
      Peak peak = scan(sums, omega_lo, step, n_steps);
      if (peak.drop <= 0.0) continue;
      peak = refine(sums, peak, step);
      if (peak.drop > best.drop) {
        best = peak;
        best_joint = i;
      }
    }
    if (best_joint < 0) break;
    // Noise alone: drop / sigma^2 ~ chi^2 with 2 degrees of freedom at each candidate, so the
    // largest of M exceeds 2 ln(M / alpha) with probability ~alpha.
    const double threshold = 2.0 * std::log(std::max(1, n_candidates) / kFalseAlarm);
    if (!(best.drop > threshold * fit.sigma2)) break;
    terms.push_back({best_joint, best.omega});
  }
  return terms;
}

JointLayoutChoice choose_joint_layout(const JointErrorModel::State& s,
                                      const std::vector<JointVector>& q_rad,
                                      const ConstPoints3Ref& error_robot_m,
                                      const JointErrorModelOptions& options) {
  JointErrorModel::State t = s;
  if (!options.periodic_terms.empty()) {
    t.layout.periodic = options.periodic_terms;
    const JointDegreeChoice c = choose_joint_degrees(t, q_rad, error_robot_m, options);
    return {c.degrees, options.periodic_terms, c.cv_rms_m};
  }
  t.layout.periodic.clear();
  const JointDegreeChoice plain = choose_joint_degrees(t, q_rad, error_robot_m, options);
  JointLayoutChoice out{plain.degrees, {}, plain.cv_rms_m};
  if (options.max_periodic_terms == 0) return out;
  const std::vector<JointPeriodicTerm> terms =
      find_periodic_terms(t, q_rad, error_robot_m, options);
  if (terms.empty()) return out;
  t.layout.periodic = terms;
  const JointDegreeChoice with = choose_joint_degrees(t, q_rad, error_robot_m, options);
  if (with.cv_rms_m < plain.cv_rms_m * (1.0 - kPeriodicGain)) {
    out = {with.degrees, terms, with.cv_rms_m};
  }
  return out;
}

}  // namespace vrreg::kinematics
