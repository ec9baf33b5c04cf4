// SPDX-License-Identifier: Apache-2.0
// The periodogram of the orientations' joint model: a transmission's cyclic angle error (periods
// of tens of degrees, far shorter than a wrist joint's travel when the tool is turned at every
// location) needs ~2 Legendre degrees per period, one sinusoid of the right frequency 2
// coefficients. A joint's term turns the marker about the joint's axis z_i(q), so its fit to a
// residual r needs only z_i . r_j and |z_i|^2 per fiducial (least squares on a sine and a
// cosine, as Lomb-Scargle).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "joint_rotation.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::detail {
namespace {

// Frequency grid step: the phase of a candidate moves by 2 pi / kOversampling over the range;
// the peak is then refined on finer grids around it.
constexpr int kOversampling = 4;
constexpr int kMaxCandidates = 2048;
constexpr int kRefineGrids = 3;  // each kRefinePoints across two steps of the previous one
constexpr int kRefinePoints = 16;
// A sinusoid has 3 unknowns with the joint's offset: fewer distinct angles cannot place one.
constexpr int kMinDistinctAngles = 8;
constexpr double kDistinctRad = 1e-9;

// Per fiducial, for one joint: its angle, z . r and |z|^2.
struct JointColumn {
  std::vector<double> q, zr, zz;
};

// The drop of |r|^2 by the least-squares fit of r on z sin(w q) and z cos(w q).
double drop_at(const JointColumn& c, double omega) {
  double ar = 0.0, br = 0.0, aa = 0.0, bb = 0.0, ab = 0.0;
  for (std::size_t j = 0; j < c.q.size(); ++j) {
    const double s = std::sin(omega * c.q[j]);
    const double k = std::cos(omega * c.q[j]);
    ar += c.zr[j] * s;
    br += c.zr[j] * k;
    aa += c.zz[j] * s * s;
    bb += c.zz[j] * k * k;
    ab += c.zz[j] * s * k;
  }
  const double det = aa * bb - ab * ab;
  if (!(det > 1e-12 * aa * bb)) return 0.0;  // sine and cosine nearly one column
  return (bb * ar * ar - 2.0 * ab * ar * br + aa * br * br) / det;
}

int distinct_angles(std::vector<double> q) {
  std::sort(q.begin(), q.end());
  int n = q.empty() ? 0 : 1;
  for (std::size_t j = 1; j < q.size(); ++j) n += q[j] - q[j - 1] > kDistinctRad ? 1 : 0;
  return n;
}

}  // namespace

PeriodicPeak strongest_periodic_term(const kinematics::SerialChain& chain,
                                     const Eigen::MatrixXd& joints_rad,
                                     const Points3& residual_robot_rad) {
  const Eigen::Index n = residual_robot_rad.cols();
  std::vector<JointColumn> columns(static_cast<std::size_t>(joints_rad.rows()));
  for (Eigen::Index j = 0; j < n; ++j) {
    const kinematics::Jacobian J = kinematics::jacobian(chain, joints_rad.col(j));
    for (Eigen::Index i = 0; i < joints_rad.rows(); ++i) {
      JointColumn& c = columns[static_cast<std::size_t>(i)];
      const Eigen::Vector3d z = J.block<3, 1>(3, i);
      c.q.push_back(joints_rad(i, j));
      c.zr.push_back(z.dot(residual_robot_rad.col(j)));
      c.zz.push_back(z.squaredNorm());
    }
  }
  PeriodicPeak best;
  for (Eigen::Index i = 0; i < joints_rad.rows(); ++i) {
    const JointColumn& c = columns[static_cast<std::size_t>(i)];
    const double range = joints_rad.row(i).maxCoeff() - joints_rad.row(i).minCoeff();
    const int n_angles = distinct_angles(c.q);
    if (!(range > 0.0) || n_angles < kMinDistinctAngles) continue;
    // From one period over the range to the mean Nyquist rate of the distinct angles.
    double step = 2.0 * std::numbers::pi / (kOversampling * range);
    const double omega_lo = 2.0 * std::numbers::pi / range;
    const double omega_hi = std::numbers::pi * (n_angles - 1) / range;
    const int n_steps =
        std::min(kMaxCandidates, static_cast<int>((omega_hi - omega_lo) / step) + 1);
    if (n_steps < 1) continue;
    best.n_candidates += n_steps;
    double peak_omega = omega_lo;
    double peak_drop = 0.0;
    for (int k = 0; k < n_steps; ++k) {
      const double omega = omega_lo + k * step;
      const double d = drop_at(c, omega);
      if (d > peak_drop) {
        peak_drop = d;
        peak_omega = omega;
      }
    }
    if (!(peak_drop > 0.0)) continue;
    for (int grid = 0; grid < kRefineGrids; ++grid) {  // within a step of the peak, finer
      const double centre = peak_omega;
      const double fine = 2.0 * step / kRefinePoints;
      for (int k = -kRefinePoints / 2; k <= kRefinePoints / 2; ++k) {
        const double omega = centre + k * fine;
        const double d = omega > 0.0 ? drop_at(c, omega) : 0.0;
        if (d > peak_drop) {
          peak_drop = d;
          peak_omega = omega;
        }
      }
      step = fine;
    }
    if (peak_drop > best.drop) {
      best.joint = static_cast<int>(i);
      best.omega_per_rad = peak_omega;
      best.drop = peak_drop;
    }
  }
  return best;
}

}  // namespace vrreg::detail
