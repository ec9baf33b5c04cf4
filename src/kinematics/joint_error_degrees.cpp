// SPDX-License-Identifier: Apache-2.0
// Degree choice of the joint-space error model by K-fold cross-validation. Every candidate model
// is a subset of the columns of one design matrix (all joints at the largest degree), so each fold
// needs only its Gram matrix: a candidate costs a few small Cholesky solves, not a refit.
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "joint_error_solve.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg::kinematics {
namespace {

// Ridge on the unit-diagonal Gram matrix: keeps the exactly degenerate directions (base rotation
// vs joint-1 offset vs trend) at a bounded, deterministic solution without moving the others.
constexpr double kDegreeRidge = 1e-9;
// A higher degree must lower the CV RMS by this fraction to be preferred (simpler on ties).
constexpr double kDegreeGain = 1e-3;
constexpr int kCandidateDegrees[] = {0,  1,  2,  3,  4,  5,  6,  8,  10, 12, 14,
                                     16, 20, 24, 28, 32, 36, 40, 48, 56, 60};

// The largest degree each joint's function may take: a third of its distinct sampled angles. On a
// grid many fiducials share a joint's angle (a column of the grid shares q1); a polynomial through
// those few values is free in between, where targets sit, and cross-validation on the fiducials
// cannot see it because held-out fiducials share the training fiducials' angles.
std::vector<int> degree_caps(const std::vector<JointVector>& q_rad, int n_joints) {
  std::vector<int> caps(static_cast<std::size_t>(n_joints), 0);
  for (int i = 0; i < n_joints; ++i) {
    caps[static_cast<std::size_t>(i)] = joint_degree_cap(distinct_joint_values(q_rad, i));
  }
  return caps;
}

struct FoldGrams {
  std::vector<Eigen::MatrixXd> gram;  // A_f^T A_f of the held-out rows, scaled columns
  std::vector<Eigen::VectorXd> rhs;   // A_f^T e_f
  std::vector<double> e_sq;           // |e_f|^2
  Eigen::MatrixXd gram_all;
  Eigen::VectorXd rhs_all;
  double n_fiducials = 0.0;
};

class DegreeScorer {
 public:
  DegreeScorer(const JointErrorLayout& full, const FoldGrams& grams) : full_(full), g_(grams) {}

  double cv_rms_m(const std::vector<int>& degrees) const {
    const std::vector<Eigen::Index> cols = columns(degrees);
    const auto p = static_cast<Eigen::Index>(cols.size());
    double sse = 0.0;
    for (std::size_t f = 0; f < g_.gram.size(); ++f) {
      Eigen::MatrixXd a(p, p);
      Eigen::VectorXd b(p);
      for (Eigen::Index r = 0; r < p; ++r) {
        b(r) = g_.rhs_all(cols[r]) - g_.rhs[f](cols[r]);
        for (Eigen::Index c = 0; c < p; ++c) {
          a(r, c) = g_.gram_all(cols[r], cols[c]) - g_.gram[f](cols[r], cols[c]);
        }
      }
      a.diagonal().array() += kDegreeRidge;
      const Eigen::VectorXd x = a.llt().solve(b);
      Eigen::MatrixXd gf(p, p);
      Eigen::VectorXd bf(p);
      for (Eigen::Index r = 0; r < p; ++r) {
        bf(r) = g_.rhs[f](cols[r]);
        for (Eigen::Index c = 0; c < p; ++c) gf(r, c) = g_.gram[f](cols[r], cols[c]);
      }
      sse += std::max(0.0, g_.e_sq[f] - 2.0 * x.dot(bf) + x.dot(gf * x));
    }
    return std::sqrt(sse / g_.n_fiducials);
  }

 private:
  std::vector<Eigen::Index> columns(const std::vector<int>& degrees) const {
    std::vector<Eigen::Index> cols;
    for (int i = 0; i < full_.n_joints(); ++i) {
      for (int k = 0; k <= degrees[static_cast<std::size_t>(i)]; ++k) {
        cols.push_back(full_.joint_column(i) + k);
      }
    }
    for (int c = full_.dh_column(); c < full_.n_columns(); ++c) cols.push_back(c);
    return cols;
  }

  const JointErrorLayout& full_;
  const FoldGrams& g_;
};

FoldGrams fold_grams(const JointErrorModel::State& full, const std::vector<JointVector>& q_rad,
                     const ConstPoints3Ref& error_robot_m, const JointErrorModelOptions& options) {
  const Eigen::MatrixXd a =
      design_matrix(full, Eigen::VectorXd::Zero(full.layout.n_columns()), q_rad);
  const Eigen::VectorXd inverse_norms = inverse_column_norms(a);
  const int n = static_cast<int>(q_rad.size());
  const std::vector<int> fold = cv_fold_of(n, options.cv_folds, options.cv_seed);
  FoldGrams g;
  g.n_fiducials = n;
  const auto p = a.cols();
  g.gram.assign(static_cast<std::size_t>(options.cv_folds), Eigen::MatrixXd::Zero(p, p));
  g.rhs.assign(static_cast<std::size_t>(options.cv_folds), Eigen::VectorXd::Zero(p));
  g.e_sq.assign(static_cast<std::size_t>(options.cv_folds), 0.0);
  for (int f = 0; f < options.cv_folds; ++f) {
    std::vector<Eigen::Index> rows;
    for (int j = 0; j < n; ++j) {
      if (fold[static_cast<std::size_t>(j)] != f) continue;
      for (int k = 0; k < 3; ++k) rows.push_back(3 * j + k);
    }
    const Eigen::MatrixXd af = a(rows, Eigen::all) * inverse_norms.asDiagonal();
    Eigen::VectorXd ef(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      ef(static_cast<Eigen::Index>(r)) = error_robot_m(rows[r] % 3, rows[r] / 3);
    }
    const auto k = static_cast<std::size_t>(f);
    g.gram[k].noalias() = af.transpose() * af;
    g.rhs[k] = af.transpose() * ef;
    g.e_sq[k] = ef.squaredNorm();
  }
  g.gram_all = Eigen::MatrixXd::Zero(p, p);
  g.rhs_all = Eigen::VectorXd::Zero(p);
  for (std::size_t k = 0; k < g.gram.size(); ++k) {
    g.gram_all += g.gram[k];
    g.rhs_all += g.rhs[k];
  }
  return g;  // gram_all has a unit diagonal (zero for negligible columns): the ridge is relative
}

}  // namespace

int distinct_joint_values(const std::vector<JointVector>& q_rad, int joint) {
  std::vector<double> values;
  values.reserve(q_rad.size());
  for (const JointVector& q : q_rad) values.push_back(q(joint));
  std::sort(values.begin(), values.end());
  int distinct = values.empty() ? 0 : 1;
  for (std::size_t k = 1; k < values.size(); ++k) {
    if (values[k] - values[k - 1] > kSameAngleRad) ++distinct;
  }
  return distinct;
}

JointDegreeChoice choose_joint_degrees(const JointErrorModel::State& s,
                                       const std::vector<JointVector>& q_rad,
                                       const ConstPoints3Ref& error_robot_m,
                                       const JointErrorModelOptions& options) {
  const int n = s.nominal.n_joints();
  VRREG_THROW_UNLESS(
      static_cast<int>(q_rad.size()) >= options.cv_folds,
      "joint error model: " << q_rad.size() << " fiducials for " << options.cv_folds << " folds");
  JointErrorModel::State full = s;
  full.layout.degrees.assign(static_cast<std::size_t>(n), options.max_joint_degree);
  const FoldGrams grams = fold_grams(full, q_rad, error_robot_m, options);
  const DegreeScorer scorer(full.layout, grams);
  std::vector<int> candidates;
  for (const int d : kCandidateDegrees) {
    if (d <= options.max_joint_degree) candidates.push_back(d);
  }
  const std::vector<int> caps = degree_caps(q_rad, n);
  // A common degree first, then each joint's own by coordinate search until nothing changes.
  JointDegreeChoice best{std::vector<int>(static_cast<std::size_t>(n), 0),
                         std::numeric_limits<double>::infinity()};
  for (const int d : candidates) {
    std::vector<int> degrees(static_cast<std::size_t>(n), d);
    for (int i = 0; i < n; ++i) {
      degrees[static_cast<std::size_t>(i)] = std::min(d, caps[static_cast<std::size_t>(i)]);
    }
    const double cv = scorer.cv_rms_m(degrees);
    if (cv < best.cv_rms_m * (1.0 - kDegreeGain)) best = {degrees, cv};
  }
  for (int pass = 0; pass < 3; ++pass) {
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      for (const int d : candidates) {
        std::vector<int> degrees = best.degrees;
        if (degrees[static_cast<std::size_t>(i)] == d || d > caps[static_cast<std::size_t>(i)])
          continue;
        degrees[static_cast<std::size_t>(i)] = d;
        const double cv = scorer.cv_rms_m(degrees);
        if (cv < best.cv_rms_m * (1.0 - kDegreeGain)) {
          best = {degrees, cv};
          changed = true;
        }
      }
    }
    if (!changed) break;
  }
  return best;
}

}  // namespace vrreg::kinematics
