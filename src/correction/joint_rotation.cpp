// SPDX-License-Identifier: Apache-2.0
#include "joint_rotation.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::detail {
namespace {

constexpr int kDegrees[] = {-1, 0, 1, 2, 4, 6, 8};
constexpr double kRelativeRankTolerance = 1e-9;

// The model's columns: n (degree + 1) joint-function columns, then 3 per link frame when the
// links' rotations are fitted.
Eigen::Index n_columns(const JointRotationTerms& m, int n_joints, bool links) {
  return n_joints * (m.degree + 1) + (links ? 3 * n_joints : 0);
}

// The design rows d g / d c of one fiducial (3 x n_columns).
void design_rows(const kinematics::SerialChain& chain, const JointRotationTerms& m, bool links,
                 const Eigen::Ref<const Eigen::VectorXd>& q_rad, Eigen::Ref<Eigen::MatrixXd> rows) {
  const kinematics::Jacobian J = kinematics::jacobian(chain, q_rad);
  const int per_joint = m.degree + 1;
  if (links) {  // link i's rotation r_i, in its own frame: R_base_i(q) r_i
    const std::vector<Eigen::Isometry3d> frames = kinematics::link_frames(chain, q_rad);
    const Eigen::Index first = q_rad.size() * per_joint;
    for (Eigen::Index i = 0; i < q_rad.size(); ++i) {
      rows.middleCols<3>(first + 3 * i) = frames[static_cast<std::size_t>(i) + 1].linear();
    }
  }
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
                       bool links, const Eigen::MatrixXd& joints_rad,
                       const std::vector<Eigen::Index>& which) {
  Eigen::MatrixXd a(3 * static_cast<Eigen::Index>(which.size()),
                    n_columns(m, static_cast<int>(joints_rad.rows()), links));
  for (std::size_t r = 0; r < which.size(); ++r) {
    design_rows(chain, m, links, joints_rad.col(which[r]),
                a.middleRows(3 * static_cast<Eigen::Index>(r), 3));
  }
  return a;
}

// The fitted coefficients into the terms: joint functions, then the links' rotations.
void store(JointRotationTerms& m, bool links, const Eigen::VectorXd& c, int n_joints) {
  const Eigen::Index joint_columns = n_joints * (m.degree + 1);
  m.coefficients = c.head(joint_columns);
  m.link_rotations_rad = links ? Eigen::VectorXd(c.tail(3 * n_joints)) : Eigen::VectorXd();
}

Eigen::VectorXd coefficients_of(const JointRotationTerms& m) {
  Eigen::VectorXd c(m.coefficients.size() + m.link_rotations_rad.size());
  c << m.coefficients, m.link_rotations_rad;
  return c;
}

Eigen::VectorXd targets(const Points3& g, const std::vector<Eigen::Index>& which) {
  Eigen::VectorXd b(3 * static_cast<Eigen::Index>(which.size()));
  for (std::size_t r = 0; r < which.size(); ++r)
    b.segment<3>(3 * static_cast<Eigen::Index>(r)) = g.col(which[r]);
  return b;
}

// Least squares on unit-norm columns, minimum norm (SVD): singular values below
// kRelativeRankTolerance of the largest are dropped, so near-redundant combinations stay small.
Eigen::VectorXd solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd scale = Eigen::VectorXd::Zero(a.cols());
  for (Eigen::Index c = 0; c < a.cols(); ++c) {
    const double norm = a.col(c).norm();
    scale(c) = norm > 0.0 ? 1.0 / norm : 0.0;
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a * scale.asDiagonal(),
                                        Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(kRelativeRankTolerance);
  return scale.asDiagonal() * svd.solve(b);
}

}  // namespace

void validate_joint_rotation(const JointRotationTerms& t, int n_joints) {
  VRREG_THROW_UNLESS(t.degree >= -1 && t.degree <= 40, "joint rotation: degree " << t.degree);
  VRREG_THROW_UNLESS(
      (t.link_rotations_rad.size() == 0 || t.link_rotations_rad.size() == 3 * n_joints) &&
          t.link_rotations_rad.allFinite(),
      "joint rotation: link rotations do not fit " << n_joints << " joints");
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
                                   const Eigen::Ref<const Eigen::VectorXd>& q_rad) {
  const bool links = terms.link_rotations_rad.size() > 0;
  if (terms.degree < 0 && !links) return Eigen::Vector3d::Zero();
  Eigen::MatrixXd rows(3, n_columns(terms, chain.n_joints(), links));
  design_rows(chain, terms, links, q_rad, rows);
  return rows * coefficients_of(terms);
}

JointRotationTerms fit_joint_rotation(const kinematics::SerialChain& chain,
                                      const Eigen::MatrixXd& joints_rad, const Points3& g_robot_rad,
                                      int folds, std::uint64_t seed) {
  const Eigen::Index n = g_robot_rad.cols();
  VRREG_THROW_UNLESS(joints_rad.cols() == n && joints_rad.rows() == chain.n_joints() && folds >= 2,
                     "joint rotation: " << joints_rad.rows() << " x " << joints_rad.cols()
                                        << " joints for " << n << " residuals");
  JointRotationTerms m;
  m.q_lo_rad = joints_rad.rowwise().minCoeff();
  m.q_hi_rad = joints_rad.rowwise().maxCoeff();
  // Folds from a seeded shuffle: the same fiducials, the same choice.
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  Random rng(seed);
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  double best_rms = std::numeric_limits<double>::infinity();
  int best_degree = -1;
  bool best_links = false;
  for (const bool links : {false, true}) {
    for (const int degree : kDegrees) {
      m.degree = degree;
      const Eigen::Index columns = n_columns(m, chain.n_joints(), links);
      if (3 * n < 2 * (columns + 1)) break;  // too few equations for this degree
      double sum_sq = 0.0;
      for (int fold = 0; fold < folds; ++fold) {
        std::vector<Eigen::Index> train, test;
        for (std::size_t r = 0; r < order.size(); ++r)
          (static_cast<int>(r % static_cast<std::size_t>(folds)) == fold ? test : train)
              .push_back(order[r]);
        const Eigen::VectorXd b_test = targets(g_robot_rad, test);
        if (columns == 0) {
          sum_sq += b_test.squaredNorm();
          continue;
        }
        const Eigen::VectorXd c =
            solve(design(chain, m, links, joints_rad, train), targets(g_robot_rad, train));
        sum_sq += (design(chain, m, links, joints_rad, test) * c - b_test).squaredNorm();
      }
      const double rms = std::sqrt(sum_sq / static_cast<double>(n));
      if (rms < best_rms) {
        best_rms = rms;
        best_degree = degree;
        best_links = links;
      }
    }
  }
  m.degree = best_degree;
  if (m.degree < 0 && !best_links) return m;
  std::vector<Eigen::Index> all(static_cast<std::size_t>(n));
  std::iota(all.begin(), all.end(), Eigen::Index{0});
  store(m, best_links,
        solve(design(chain, m, best_links, joints_rad, all), targets(g_robot_rad, all)),
        chain.n_joints());
  return m;
}

}  // namespace vrreg::detail
