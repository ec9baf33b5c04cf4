// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/plan_next.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_set>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg/planning/cube_tour.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg::planning {
// Unity builds share one translation unit per module: the helpers live in their own namespace.
namespace next_batch {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A reachable lattice node: its joints in its nearest part point's configuration.
struct Candidate {
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();
  Eigen::Vector3i index = Eigen::Vector3i::Zero();
  int part = 0;
  JointChoice joints{};
};

void check_parts(const std::vector<PartPoint>& parts) {
  VRREG_THROW_UNLESS(!parts.empty(), "plan next: no part points");
  std::unordered_set<std::string> names;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    VRREG_THROW_UNLESS(!parts[i].name.empty(), "plan next: part point " << i + 1 << " has no name");
    VRREG_THROW_UNLESS(parts[i].robot_m.allFinite(),
                       "plan next: part point '" << parts[i].name << "' has a non-finite position");
    VRREG_THROW_UNLESS(names.insert(parts[i].name).second,
                       "plan next: two part points are named '" << parts[i].name << "'");
  }
}

void check_measured(const MeasuredFiducials& measured) {
  VRREG_THROW_UNLESS(measured.robot_m.cols() == measured.sensor_m.cols(),
                     "plan next: " << measured.robot_m.cols() << " robot positions but "
                                   << measured.sensor_m.cols() << " sensor positions");
  VRREG_THROW_UNLESS(measured.robot_m.allFinite() && measured.sensor_m.allFinite(),
                     "plan next: a measured fiducial has a non-finite position");
}

int nearest_part(const std::vector<PartPoint>& parts, const Eigen::Vector3d& point_m) {
  int best = 0;
  for (std::size_t i = 1; i < parts.size(); ++i) {
    if ((parts[i].robot_m - point_m).squaredNorm() <
        (parts[static_cast<std::size_t>(best)].robot_m - point_m).squaredNorm()) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

// The position nearest robot_m [m] whose millimetre value is a multiple of 1e-9 mm and prints as
// such (the plan CSV writes m_to_mm of it: 400, not 399.99999999999994).
Eigen::Vector3d snapped_m(const Eigen::Vector3d& robot_m) {
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    const double mm = std::round(units::m_to_mm(robot_m(i)) * 1e9) / 1e9;
    double m = units::mm_to_m(mm);
    // One or two ulps either way make the round trip exact where the product rounds off.
    for (int step = 0; step < 4 && units::m_to_mm(m) != mm; ++step) {
      m = std::nextafter(m, units::m_to_mm(m) < mm ? std::numeric_limits<double>::infinity()
                                                   : -std::numeric_limits<double>::infinity());
    }
    out(i) = m;
  }
  return out;
}

// Lattice nodes over the parts' bounding box grown by the margin, centred on the box, that are
// reachable in their nearest part point's configuration and not already measured.
std::vector<Candidate> make_candidates(const kinematics::SerialChain& chain,
                                       const std::vector<PartPoint>& parts,
                                       const std::vector<PartPlan>& plans,
                                       const MeasuredFiducials& measured,
                                       const PlanNextOptions& options) {
  Eigen::Vector3d lo = parts.front().robot_m;
  Eigen::Vector3d hi = lo;
  for (const PartPoint& p : parts) {
    lo = lo.cwiseMin(p.robot_m);
    hi = hi.cwiseMax(p.robot_m);
  }
  lo.array() -= options.margin_m;
  hi.array() += options.margin_m;
  const double a = options.candidate_spacing_m;
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  Eigen::Vector3i n;
  for (int i = 0; i < 3; ++i) n(i) = static_cast<int>(std::floor((hi(i) - lo(i)) / a + 1e-9)) + 1;
  const long long total = static_cast<long long>(n.x()) * n.y() * n.z();
  VRREG_THROW_UNLESS(total <= options.max_candidates,
                     "plan next: " << total << " candidate locations, more than "
                                   << options.max_candidates << "; use a larger candidate spacing");
  const Eigen::Vector3d origin = centre - 0.5 * a * (n.cast<double>() - Eigen::Vector3d::Ones());
  std::vector<Candidate> out;
  for (int iz = 0; iz < n.z(); ++iz) {
    for (int iy = 0; iy < n.y(); ++iy) {
      for (int ix = 0; ix < n.x(); ++ix) {
        Candidate c;
        c.index = {ix, iy, iz};
        c.robot_m = snapped_m(origin + a * c.index.cast<double>());
        bool taken = false;
        for (Eigen::Index j = 0; j < measured.robot_m.cols() && !taken; ++j) {
          taken = (measured.robot_m.col(j) - c.robot_m).norm() < 0.5 * a;
        }
        if (taken) continue;
        c.part = nearest_part(parts, c.robot_m);
        const PartPlan& part = plans[static_cast<std::size_t>(c.part)];
        c.joints = nearest_joints(chain, c.robot_m, part.q_rad, options.arm);
        if (!c.joints.ok() || !(c.joints.config == part.config)) continue;
        out.push_back(std::move(c));
      }
    }
  }
  return out;
}

// Greedy maximin: each pick the candidate farthest from every measured or picked location (the
// first, with nothing measured, the one nearest the parts' centroid).
std::vector<std::size_t> space_filling(const std::vector<Candidate>& candidates,
                                       const std::vector<PartPoint>& parts,
                                       const MeasuredFiducials& measured, int count) {
  std::vector<double> nearest(candidates.size(), std::numeric_limits<double>::infinity());
  auto take = [&](const Eigen::Vector3d& point_m) {
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      nearest[c] = std::min(nearest[c], (candidates[c].robot_m - point_m).norm());
    }
  };
  for (Eigen::Index j = 0; j < measured.robot_m.cols(); ++j) take(measured.robot_m.col(j));
  std::vector<std::size_t> picked;
  if (measured.robot_m.cols() == 0 && !candidates.empty()) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const PartPoint& p : parts) centroid += p.robot_m;
    centroid /= static_cast<double>(parts.size());
    std::size_t first = 0;
    for (std::size_t c = 1; c < candidates.size(); ++c) {
      if ((candidates[c].robot_m - centroid).squaredNorm() <
          (candidates[first].robot_m - centroid).squaredNorm()) {
        first = c;
      }
    }
    picked.push_back(first);
    take(candidates[first].robot_m);
  }
  while (static_cast<int>(picked.size()) < count) {
    std::size_t best = candidates.size();
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (nearest[c] > 0.0 && (best == candidates.size() || nearest[c] > nearest[best])) best = c;
    }
    if (best == candidates.size()) break;
    picked.push_back(best);
    take(candidates[best].robot_m);
  }
  return picked;
}

Points3 columns_of(const std::vector<Candidate>& candidates) {
  Points3 out(3, static_cast<Eigen::Index>(candidates.size()));
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    out.col(static_cast<Eigen::Index>(c)) = candidates[c].robot_m;
  }
  return out;
}

Points3 with_columns(const Points3& design_m, const Points3& extra_m) {
  Points3 out(3, design_m.cols() + extra_m.cols());
  out << design_m, extra_m;
  return out;
}

// Predicted sd of a corrected point per part [m] (method_kriging: the latent posterior variance
// times the leave-one-out factor squared, plus the nugget, summed over axes).
Eigen::VectorXd part_sd_m(const PlanNextResult& r, const Points3& design_m,
                          const Points3& parts_m) {
  Eigen::VectorXd variance = Eigen::VectorXd::Zero(parts_m.cols());
  for (std::size_t a = 0; a < 3; ++a) {
    const double nugget = r.model[a].hyperparameters.nugget_sd_m;
    variance += r.latent_sd_scale[a] * r.latent_sd_scale[a] *
                    kriging_posterior_variance(design_m, parts_m, r.model[a]) +
                Eigen::VectorXd::Constant(parts_m.cols(), nugget * nugget);
  }
  return variance.cwiseSqrt();
}

double rms(const Eigen::VectorXd& sd_m) {
  return std::sqrt(sd_m.squaredNorm() / static_cast<double>(sd_m.size()));
}

// Greedy: each pick maximises sum_a scale_a^2 sum_p cov_a(p, c)^2 / (var_a(c) + nugget_a^2),
// the drop of the summed posterior variance at the parts when c is measured (rank-one update).
// All positions are the model's inputs (KrigingCorrectorDesign::inputs). The posterior given the
// measured fiducials is computed once; each pick b then conditions it on one more noisy
// observation, Sigma <- Sigma - Sigma(., b) Sigma(b, .) / (Sigma(b, b) + nugget^2), which is the
// universal-kriging posterior of the enlarged design (the trend's flat prior conditions the same
// way), without refactoring the design per pick.
std::vector<std::size_t> greedy_variance(const PlanNextResult& r, const Points3& candidates_m,
                                         const Points3& measured_m, const Points3& parts_m,
                                         int count) {
  const auto n_candidates = static_cast<std::size_t>(candidates_m.cols());
  const Eigen::Index nc = candidates_m.cols();
  std::array<Eigen::MatrixXd, 3> cov_pc;  // parts x candidates, given everything so far
  std::array<Eigen::VectorXd, 3> var_c;   // candidates
  // Per axis, the updates so far: column j is Sigma_j(., b_j) / sqrt(Sigma_j(b_j, b_j) + nugget^2)
  // over the candidates, so that Sigma_k(c, b) = Sigma_0(c, b) - sum_j u_j(c) u_j(b).
  std::array<Eigen::MatrixXd, 3> updates;
  for (std::size_t a = 0; a < 3; ++a) {
    cov_pc[a] = kriging_posterior_covariance(measured_m, parts_m, candidates_m, r.model[a]);
    var_c[a] = kriging_posterior_variance(measured_m, candidates_m, r.model[a]);
    updates[a].resize(nc, 0);
  }
  std::vector<std::size_t> picked;
  std::vector<bool> used(n_candidates, false);
  while (static_cast<int>(picked.size()) < count) {
    Eigen::VectorXd gain = Eigen::VectorXd::Zero(nc);
    for (std::size_t a = 0; a < 3; ++a) {
      const double nugget2 =
          r.model[a].hyperparameters.nugget_sd_m * r.model[a].hyperparameters.nugget_sd_m;
      const double scale2 = r.latent_sd_scale[a] * r.latent_sd_scale[a];
      gain += scale2 * (cov_pc[a].colwise().squaredNorm().transpose().array() /
                        (var_c[a].array() + nugget2).max(std::numeric_limits<double>::min()))
                           .matrix();
    }
    std::size_t best = n_candidates;
    for (std::size_t c = 0; c < n_candidates; ++c) {
      if (used[c]) continue;
      if (best == n_candidates ||
          gain(static_cast<Eigen::Index>(c)) > gain(static_cast<Eigen::Index>(best))) {
        best = c;
      }
    }
    if (best == n_candidates) break;
    used[best] = true;
    picked.push_back(best);
    if (static_cast<int>(picked.size()) == count) break;
    const auto b = static_cast<Eigen::Index>(best);
    for (std::size_t a = 0; a < 3; ++a) {
      const double nugget2 =
          r.model[a].hyperparameters.nugget_sd_m * r.model[a].hyperparameters.nugget_sd_m;
      const double denom = std::sqrt(std::max(var_c[a](b) + nugget2, 0.0));
      if (!(denom > 0.0)) continue;  // a noiseless, known point: nothing left to learn there
      Eigen::VectorXd cov_cb =
          kriging_posterior_covariance(measured_m, candidates_m, candidates_m.col(b), r.model[a])
              .col(0);
      if (updates[a].cols() > 0) cov_cb -= updates[a] * updates[a].row(b).transpose();
      const Eigen::VectorXd u = cov_cb / denom;
      const Eigen::VectorXd w = cov_pc[a].col(b) / denom;
      cov_pc[a].noalias() -= w * u.transpose();
      var_c[a] -= u.cwiseAbs2();
      updates[a].conservativeResize(Eigen::NoChange, updates[a].cols() + 1);
      updates[a].col(updates[a].cols() - 1) = u;
    }
  }
  return picked;
}

// The kriging corrector's model fitted on the fiducial corrections (Eq. 6) of the rigid
// registration of the measured fiducials, as `register --interpolation kriging` fits it; or the
// given hyperparameters on Cartesian inputs.
KrigingCorrectorDesign fit_model(const MeasuredFiducials& measured, const PlanNextOptions& options,
                                 PlanNextResult& r) {
  KrigingCorrectorDesign design;
  if (options.hyperparameters) {
    const int degree = kriging_trend_degree_for(measured.robot_m.cols());
    for (std::size_t a = 0; a < 3; ++a) {
      design.axes[a] = {(*options.hyperparameters)[a], options.kernel, degree};
    }
  } else {
    const RegistrationResult reg = register_rigid(measured.sensor_m, measured.robot_m);
    design = fit_kriging_corrector_design(
        reg.T_robot_sensor, measured.robot_m,
        fiducial_corrections(reg.T_robot_sensor, measured.sensor_m, measured.robot_m),
        options.noise_sd_m);
  }
  r.model = design.axes;
  r.latent_sd_scale = design.latent_sd_scale;
  r.has_model = true;
  return design;
}

// The correction's own sd at the parts, when it gave one for every part (finite, >= 0).
void use_correction_sd(const CorrectionSd& answer, PlanNextResult& r) {
  if (!answer.sd_m) {
    r.sd_note = answer.note;
    return;
  }
  VRREG_THROW_UNLESS(answer.sd_m->size() == static_cast<Eigen::Index>(r.parts.size()),
                     "plan next: the correction's sd has " << answer.sd_m->size()
                                                           << " values for " << r.parts.size()
                                                           << " part points");
  VRREG_THROW_UNLESS(answer.sd_m->allFinite() && (answer.sd_m->array() >= 0.0).all(),
                     "plan next: the correction's sd at the parts must be finite and >= 0");
  r.part_sd_now_m = *answer.sd_m;
  r.sd_method = answer.method.empty() ? std::string("correction") : answer.method;
}

// Visiting order of the batch: the shortest open tour plan_cube_tour finds over the points.
std::vector<std::size_t> visiting_order(const std::vector<Candidate>& candidates,
                                        const std::vector<std::size_t>& picked, double& path_m) {
  path_m = 0.0;
  if (picked.size() < 2) return picked;
  Points3 points_m(3, static_cast<Eigen::Index>(picked.size()));
  for (std::size_t k = 0; k < picked.size(); ++k) {
    points_m.col(static_cast<Eigen::Index>(k)) = candidates[picked[k]].robot_m;
  }
  const Points3 no_offset = Points3::Zero(3, 1);
  const CubeTour tour = plan_cube_tour(points_m, no_offset, no_offset);
  path_m = tour.between_cubes_m;
  std::vector<std::size_t> out;
  for (const int k : tour.order) out.push_back(picked[static_cast<std::size_t>(k)]);
  return out;
}

}  // namespace

void validate_options(const PlanNextOptions& o, const kinematics::SerialChain& chain) {
  if (o.goal_floor_multiple) {
    VRREG_THROW_UNLESS(o.goal_sd_m == 0.0,
                       "plan next: give the goal as an sd or as a multiple of the noise floor, not "
                       "both");
    VRREG_THROW_UNLESS(
        std::isfinite(*o.goal_floor_multiple) && *o.goal_floor_multiple > 0.0,
        "plan next: the goal's noise floor multiple must be finite and positive, got "
            << *o.goal_floor_multiple);
  } else {
    VRREG_THROW_UNLESS(std::isfinite(o.goal_sd_m) && o.goal_sd_m > 0.0,
                       "plan next: the goal sd must be finite and positive, got "
                           << units::m_to_mm(o.goal_sd_m) << " mm");
  }
  VRREG_THROW_UNLESS(std::isfinite(o.sigma_rep_m) && o.sigma_rep_m >= 0.0,
                     "plan next: sigma_rep must be finite and >= 0");
  VRREG_THROW_UNLESS(o.batch_size >= 1, "plan next: batch size must be >= 1, got " << o.batch_size);
  VRREG_THROW_UNLESS(o.budget >= 1, "plan next: budget must be >= 1, got " << o.budget);
  VRREG_THROW_UNLESS(std::isfinite(o.candidate_spacing_m) && o.candidate_spacing_m > 0.0,
                     "plan next: candidate spacing must be finite and positive");
  VRREG_THROW_UNLESS(std::isfinite(o.margin_m) && o.margin_m >= 0.0,
                     "plan next: margin must be finite and >= 0");
  VRREG_THROW_UNLESS(o.min_fit_fiducials >= 4,
                     "plan next: min_fit_fiducials must be >= 4, got " << o.min_fit_fiducials);
  VRREG_THROW_UNLESS(
      std::isfinite(o.min_relative_gain) && o.min_relative_gain >= 0.0 && o.min_relative_gain < 1.0,
      "plan next: min_relative_gain must be in [0, 1), got " << o.min_relative_gain);
  VRREG_THROW_UNLESS(!o.noise_sd_m || (std::isfinite(*o.noise_sd_m) && *o.noise_sd_m >= 0.0),
                     "plan next: noise sd must be finite and >= 0");
  VRREG_THROW_UNLESS(!o.label_prefix.empty(), "plan next: empty label prefix");
  VRREG_THROW_UNLESS(o.max_candidates > 0, "plan next: max_candidates must be positive");
  o.arm.validate(chain);
}

PlanNextResult run(const kinematics::SerialChain& chain, const std::vector<PartPoint>& parts,
                   const MeasuredFiducials& measured, const PlanNextOptions& options) {
  validate_options(options, chain);
  check_parts(parts);
  check_measured(measured);
  PlanNextResult r;
  r.n_measured = measured.robot_m.cols();
  r.rms_sd_now_m = kNaN;
  r.rms_sd_after_m = kNaN;
  // The noise floor sqrt(3 (sigma_rep^2 + sigma_opt^2 / K)) (design.md), noise_sd_m being
  // sigma_opt / sqrt(K).
  r.noise_floor_m = options.noise_sd_m
                        ? std::sqrt(3.0 * (options.sigma_rep_m * options.sigma_rep_m +
                                           *options.noise_sd_m * *options.noise_sd_m))
                        : kNaN;
  r.goal_sd_m = !options.goal_floor_multiple     ? options.goal_sd_m
                : std::isfinite(r.noise_floor_m) ? *options.goal_floor_multiple * r.noise_floor_m
                                                 : kNaN;
  Points3 parts_m(3, static_cast<Eigen::Index>(parts.size()));
  std::vector<std::string> unreachable;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    parts_m.col(static_cast<Eigen::Index>(i)) = parts[i].robot_m;
    PartPlan& plan = r.parts.emplace_back();
    plan.name = parts[i].name;
    plan.robot_m = parts[i].robot_m;
    const JointChoice at_part = part_joints(chain, parts[i].robot_m, options.arm);
    plan.reachable = at_part.ok();
    if (!at_part.ok()) {
      unreachable.push_back(parts[i].name + " (" + at_part.message + ")");
      continue;
    }
    plan.q_rad = at_part.q_rad;
    plan.config = at_part.config;
    plan.visit_rank = static_cast<int>(i);
  }
  if (!unreachable.empty()) {
    r.status = PlanStatus::kUnreachable;
    std::ostringstream out;
    out << unreachable.size() << " part points cannot be reached with the given tool orientation: "
        << unreachable.front();
    r.message = out.str();
    return r;
  }

  const Eigen::Index j = r.n_measured;
  KrigingCorrectorDesign design;
  if (j >= options.min_fit_fiducials) {
    design = fit_model(measured, options, r);
    r.part_sd_now_m = part_sd_m(r, design.inputs(measured.robot_m), design.inputs(parts_m));
    if (options.correction_sd) use_correction_sd(options.correction_sd(r.parts), r);
    r.rms_sd_now_m = rms(r.part_sd_now_m);
  }
  const int room = std::max(0, options.budget - static_cast<int>(j));
  // NaN (the floor not known yet) never compares true: no stop on the goal.
  if (r.has_model && r.rms_sd_now_m <= r.goal_sd_m) {
    r.decision = PlanNextDecision::kStop;
    r.reason = "the goal is reached";
  } else if (room == 0) {
    r.decision = PlanNextDecision::kStop;
    r.reason = "the budget is spent";
  }
  if (r.decision == PlanNextDecision::kStop) {
    r.part_sd_after_m = r.part_sd_now_m;
    r.rms_sd_after_m = r.rms_sd_now_m;
    return r;
  }

  const std::vector<Candidate> candidates =
      make_candidates(chain, parts, r.parts, measured, options);
  r.n_candidates = static_cast<Eigen::Index>(candidates.size());
  std::vector<std::size_t> picked;
  if (!r.has_model) {
    r.space_filling = true;
    const int count = std::min(
        room, std::max(options.batch_size, options.min_fit_fiducials - static_cast<int>(j)));
    picked = space_filling(candidates, parts, measured, count);
  } else {
    picked =
        greedy_variance(r, design.inputs(columns_of(candidates)), design.inputs(measured.robot_m),
                        design.inputs(parts_m), std::min(room, options.batch_size));
  }
  if (picked.empty()) {
    r.decision = PlanNextDecision::kStop;
    r.reason = "no reachable candidate location is left";
    r.part_sd_after_m = r.part_sd_now_m;
    r.rms_sd_after_m = r.rms_sd_now_m;
    return r;
  }
  picked = visiting_order(candidates, picked, r.path_m);
  Points3 batch_m(3, static_cast<Eigen::Index>(picked.size()));
  for (std::size_t k = 0; k < picked.size(); ++k) {
    const Candidate& c = candidates[picked[k]];
    batch_m.col(static_cast<Eigen::Index>(k)) = c.robot_m;
    PlannedLocation& loc = r.locations.emplace_back();
    loc.point = options.label_prefix + std::to_string(j + static_cast<Eigen::Index>(k) + 1);
    loc.role = Role::kFiducial;
    loc.part = c.part;
    loc.grid_index = c.index;
    loc.robot_m = c.robot_m;
    loc.q_rad = c.joints.q_rad;
    loc.config = c.joints.config;
    loc.joint_distance_rad = c.joints.distance_rad;
  }
  if (r.has_model) {
    r.part_sd_after_m = part_sd_m(r, design.inputs(with_columns(measured.robot_m, batch_m)),
                                  design.inputs(parts_m));
    r.rms_sd_after_m = rms(r.part_sd_after_m);
    // Another method's sd after a batch is not known before it is measured: kriging's expected
    // drop is no guide to it (measured: on the UR5 test bed kriging levels off at its nugget
    // while the joint-space model's sd still falls), so no "after" and no 1 % rule for it.
    if (r.sd_method != "kriging") {
      r.part_sd_after_m = Eigen::VectorXd::Constant(r.part_sd_now_m.size(), kNaN);
      r.rms_sd_after_m = kNaN;
    }
  }
  if (r.has_model && r.sd_method == "kriging" &&
      r.rms_sd_after_m > (1.0 - options.min_relative_gain) * r.rms_sd_now_m) {
    r.decision = PlanNextDecision::kStop;
    r.reason =
        fmt::format("another batch is expected to lower the predicted sd by less than {:g} %",
                    100.0 * options.min_relative_gain);
    r.locations.clear();
    r.path_m = 0.0;
    r.part_sd_after_m = r.part_sd_now_m;
    r.rms_sd_after_m = r.rms_sd_now_m;
    return r;
  }
  r.reason = !r.has_model ? "too few fiducials for a model: a space-filling batch"
             : r.rms_sd_after_m <= r.goal_sd_m ? "the batch is expected to reach the goal"
             : std::isnan(r.goal_sd_m)
                 ? "the noise floor, and so the goal, is not known yet (no repeat readings)"
                 : "the goal is not reached yet";
  if (!r.has_model && std::isnan(r.goal_sd_m)) {
    r.reason += "; the noise floor, and so the goal, is not known yet (no repeat readings)";
  }
  return r;
}

}  // namespace next_batch

const char* to_string(PlanNextDecision decision) {
  return decision == PlanNextDecision::kStop ? "stop" : "continue";
}

FiducialsWithNoise measured_fiducials(const MeasurementSet& set) {
  const std::vector<std::size_t> rows = set.select(Role::kFiducial);
  std::vector<Location> locations;
  for (const std::size_t i : rows) {
    VRREG_THROW_UNLESS(set.locations[i].has_robot,
                       "fiducial '" << set.locations[i].point << "' has no robot position");
    locations.push_back(set.locations[i]);
  }
  FiducialsWithNoise out;
  out.fiducials = {set.robot_points(rows), set.sensor_points(rows)};
  if (const std::optional<double> opt = sigma_opt_m(locations); opt && !locations.empty()) {
    out.noise_sd_m = *opt / std::sqrt(static_cast<double>(median_readings(locations)));
  }
  return out;
}

void PlanNextOptions::validate(const kinematics::SerialChain& chain) const {
  next_batch::validate_options(*this, chain);
}

PlanNextResult plan_next(const kinematics::SerialChain& chain, const std::vector<PartPoint>& parts,
                         const MeasuredFiducials& measured, const PlanNextOptions& options) {
  return next_batch::run(chain, parts, measured, options);
}

}  // namespace vrreg::planning

namespace vrreg::planning {

std::vector<PartPoint> volume_part_points(const Eigen::Vector3d& min_m, const Eigen::Vector3d& max_m,
                                          double spacing_m, long long max_points) {
  VRREG_THROW_UNLESS(min_m.allFinite() && max_m.allFinite(),
                     "plan next: the work volume's corners must be finite");
  VRREG_THROW_UNLESS(std::isfinite(spacing_m) && spacing_m > 0.0,
                     "plan next: the volume spacing must be finite and positive, got "
                         << units::m_to_mm(spacing_m) << " mm");
  Eigen::Vector3i n;
  Eigen::Vector3d first_m;
  for (int a = 0; a < 3; ++a) {
    const double extent_m = max_m(a) - min_m(a);
    VRREG_THROW_UNLESS(extent_m >= 0.0, "plan next: the work volume's "
                                            << "xyz"[a] << " range is empty ("
                                            << units::m_to_mm(min_m(a)) << " > "
                                            << units::m_to_mm(max_m(a)) << " mm)");
    // A whisker of tolerance: a 200 mm box at 50 mm holds 5 nodes despite rounding.
    const double cells = std::floor(extent_m / spacing_m + 1e-9);
    VRREG_THROW_UNLESS(cells < 1e6, "plan next: the work volume holds too many part points");
    n(a) = static_cast<int>(cells) + 1;
    first_m(a) = min_m(a) + 0.5 * (extent_m - cells * spacing_m);
  }
  const long long total = static_cast<long long>(n(0)) * n(1) * n(2);
  VRREG_THROW_UNLESS(total <= max_points, "plan next: the work volume at "
                                              << units::m_to_mm(spacing_m) << " mm holds " << total
                                              << " part points, more than " << max_points
                                              << " (use a larger spacing)");
  std::vector<PartPoint> parts;
  parts.reserve(static_cast<std::size_t>(total));
  for (int iz = 0; iz < n(2); ++iz) {
    for (int iy = 0; iy < n(1); ++iy) {
      for (int ix = 0; ix < n(0); ++ix) {
        const Eigen::Vector3d p_m = first_m + spacing_m * Eigen::Vector3d(ix, iy, iz);
        parts.push_back({"v" + std::to_string(parts.size() + 1), next_batch::snapped_m(p_m)});
      }
    }
  }
  return parts;
}

}  // namespace vrreg::planning
