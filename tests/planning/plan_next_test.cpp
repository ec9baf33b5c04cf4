// SPDX-License-Identifier: Apache-2.0
// Adaptive planning (plan_next): the space-filling first batch, the greedy variance-reduction
// batches against a brute-force universal-kriging reference written here from the textbook
// augmented system, the predicted sd after a batch, and the stopping rule.
#include "vrreg/planning/plan_next.hpp"

#include <Eigen/LU>
#include <cmath>
#include <set>

#include "planning_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/correction/kriging_design.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg_test.hpp"

namespace vrreg::planning {
namespace {

using kinematics::SerialChain;
using testing::ur5_with_sphere;

std::vector<PartPoint> three_parts() {
  return {{"hole_A", {0.42, -0.14, 0.25}},
          {"hole_B", {0.48, -0.12, 0.25}},
          {"pin_C", {0.46, -0.06, 0.26}}};
}

PlanNextOptions small_options() {
  PlanNextOptions o;
  o.goal_sd_m = 0.05e-3;
  o.batch_size = 4;
  o.budget = 40;
  o.candidate_spacing_m = 0.01;
  o.margin_m = 0.02;
  return o;
}

// Reference: Matern 5/2 with anisotropic lengths.
double matern(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const KrigingHyperparameters& h) {
  const double r = ((a - b).array() / h.length_m.array()).matrix().norm();
  const double s5 = std::sqrt(5.0) * r;
  return h.signal_sd_m * h.signal_sd_m * (1.0 + s5 + 5.0 * r * r / 3.0) * std::exp(-s5);
}

// Reference: monomials of degree <= d in the raw coordinates (another basis of the same space).
Eigen::VectorXd monomials(const Eigen::Vector3d& x, int degree) {
  std::vector<double> f{1.0};
  if (degree >= 1) f.insert(f.end(), {x(0), x(1), x(2)});
  if (degree >= 2) {
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) f.push_back(x(i) * x(j));
    }
  }
  return Eigen::Map<Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size()));
}

// Universal-kriging error covariance from the augmented system M = [K + n^2 I, F; F', 0]:
// c(a, b) - [k_a; f_a]' M^-1 [k_b; f_b].
double reference_covariance(const Points3& design_m, const Eigen::Vector3d& a,
                            const Eigen::Vector3d& b, const KrigingDesignModel& model) {
  const KrigingHyperparameters& h = model.hyperparameters;
  const Eigen::Index j = design_m.cols();
  const auto m = monomials(design_m.col(0), model.trend_degree).size();
  Eigen::MatrixXd big = Eigen::MatrixXd::Zero(j + m, j + m);
  for (Eigen::Index p = 0; p < j; ++p) {
    for (Eigen::Index q = 0; q < j; ++q) big(p, q) = matern(design_m.col(p), design_m.col(q), h);
    big(p, p) += h.nugget_sd_m * h.nugget_sd_m;
    const Eigen::VectorXd f = monomials(design_m.col(p), model.trend_degree);
    big.block(p, j, 1, m) = f.transpose();
    big.block(j, p, m, 1) = f;
  }
  auto rhs = [&](const Eigen::Vector3d& x) {
    Eigen::VectorXd v(j + m);
    for (Eigen::Index p = 0; p < j; ++p) v(p) = matern(design_m.col(p), x, h);
    v.tail(m) = monomials(x, model.trend_degree);
    return v;
  };
  return matern(a, b, h) - rhs(a).dot(big.fullPivLu().solve(rhs(b)));
}

double reference_summed_variance(const Points3& design_m, const Points3& parts_m,
                                 const std::array<KrigingDesignModel, 3>& model) {
  double sum = 0.0;
  for (const KrigingDesignModel& axis : model) {
    for (Eigen::Index p = 0; p < parts_m.cols(); ++p) {
      sum += reference_covariance(design_m, parts_m.col(p), parts_m.col(p), axis);
    }
  }
  return sum;
}

Points3 parts_matrix(const std::vector<PartPoint>& parts) {
  Points3 out(3, static_cast<Eigen::Index>(parts.size()));
  for (std::size_t i = 0; i < parts.size(); ++i)
    out.col(static_cast<Eigen::Index>(i)) = parts[i].robot_m;
  return out;
}

Points3 batch_matrix(const PlanNextResult& r) {
  Points3 out(3, static_cast<Eigen::Index>(r.locations.size()));
  for (std::size_t k = 0; k < r.locations.size(); ++k) {
    out.col(static_cast<Eigen::Index>(k)) = r.locations[k].robot_m;
  }
  return out;
}

Points3 joined(const Points3& a, const Points3& b) {
  Points3 out(3, a.cols() + b.cols());
  out << a, b;
  return out;
}

// Every location reaches its position with the planned orientation, within the joint limits, in
// its part point's configuration.
void check_reachable(const SerialChain& chain, const PlanNextResult& r, const PlanNextOptions& o) {
  for (const PlannedLocation& l : r.locations) {
    const Eigen::Isometry3d t = kinematics::forward_kinematics(chain, l.q_rad);
    EXPECT_LE((t.translation() - l.robot_m).norm(), 1e-9) << l.point;
    EXPECT_LE(kinematics::rotation_angle_between(t.linear(), o.arm.R_base_tcp), 1e-9) << l.point;
    EXPECT_TRUE(chain.within_limits(l.q_rad)) << l.point;
    EXPECT_EQ(l.config, r.parts[static_cast<std::size_t>(l.part)].config) << l.point;
  }
}

std::array<KrigingHyperparameters, 3> known_hyperparameters() {
  std::array<KrigingHyperparameters, 3> h;
  h[0] = {Eigen::Vector3d(0.05, 0.07, 0.04), 0.2e-3, 0.02e-3};
  h[1] = {Eigen::Vector3d(0.08, 0.05, 0.06), 0.15e-3, 0.03e-3};
  h[2] = {Eigen::Vector3d(0.06, 0.06, 0.03), 0.1e-3, 0.02e-3};
  return h;
}

// The second call of a loop: the three parts, the first (space-filling) batch measured without
// error, the known hyperparameters.
struct SecondCall {
  SerialChain chain = ur5_with_sphere();
  PlanNextOptions o = small_options();
  std::vector<PartPoint> parts = three_parts();
  MeasuredFiducials measured{};
  SecondCall() {
    const PlanNextResult first = plan_next(chain, parts, {}, o);
    measured = {batch_matrix(first), batch_matrix(first)};
    o.hyperparameters = known_hyperparameters();
  }
};

TEST(KrigingDesign, PosteriorCovarianceMatchesTheAugmentedSystem) {
  Random rng(7);
  const Points3 design_m = testing::random_points(rng, 45, 0.08, {0.45, -0.1, 0.25});
  const Points3 query_m = testing::random_points(rng, 5, 0.1, {0.45, -0.1, 0.25});
  for (int degree = 0; degree <= 2; ++degree) {
    const KrigingDesignModel model{known_hyperparameters()[1], KrigingKernel::matern52, degree};
    const Eigen::MatrixXd cov = kriging_posterior_covariance(design_m, query_m, query_m, model);
    const Eigen::VectorXd var = kriging_posterior_variance(design_m, query_m, model);
    for (Eigen::Index a = 0; a < query_m.cols(); ++a) {
      for (Eigen::Index b = 0; b < query_m.cols(); ++b) {
        const double ref = reference_covariance(design_m, query_m.col(a), query_m.col(b), model);
        EXPECT_NEAR(cov(a, b), ref, 1e-7 * std::abs(cov(a, a))) << degree;
      }
      EXPECT_NEAR(var(a), cov(a, a), 1e-9 * cov(a, a)) << degree;
    }
  }
  EXPECT_THROW((void)kriging_posterior_variance(design_m.leftCols(3), query_m,
                                                {known_hyperparameters()[0], {}, 2}),
               InputError);
}

TEST(PlanNext, FirstBatchIsSpaceFillingAndReachable) {
  const SerialChain chain = ur5_with_sphere();
  const PlanNextOptions o = small_options();
  const PlanNextResult r = plan_next(chain, three_parts(), {}, o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(r.space_filling);
  EXPECT_FALSE(r.has_model);
  EXPECT_EQ(r.decision, PlanNextDecision::kContinue);
  ASSERT_EQ(static_cast<int>(r.locations.size()), o.min_fit_fiducials);  // batch 4 < 12
  check_reachable(chain, r, o);
  // Inside the parts' box grown by the margin; unique labels.
  std::set<std::string> labels;
  for (const PlannedLocation& l : r.locations) {
    EXPECT_TRUE(labels.insert(l.point).second);
    EXPECT_GE(l.robot_m.x(), 0.42 - o.margin_m - 1e-12);
    EXPECT_LE(l.robot_m.x(), 0.48 + o.margin_m + 1e-12);
    EXPECT_GE(l.robot_m.z(), 0.25 - o.margin_m - 1e-12);
    EXPECT_LE(l.robot_m.z(), 0.26 + o.margin_m + 1e-12);
  }
  // Greedy maximin covers the volume: no lattice node is farther from the batch than the
  // batch's closest pair (every node is reachable in this cell, so the lattice is the candidate
  // set).
  const Points3 batch_m = batch_matrix(r);
  double separation = INFINITY;
  for (Eigen::Index a = 0; a < batch_m.cols(); ++a) {
    for (Eigen::Index b = a + 1; b < batch_m.cols(); ++b) {
      separation = std::min(separation, (batch_m.col(a) - batch_m.col(b)).norm());
    }
  }
  const Eigen::Vector3i n(11, 13, 6);  // (0.06 + 0.04) / 0.01 + 1, ...
  EXPECT_EQ(r.n_candidates, n.prod());
  const Eigen::Vector3d lo(0.40, -0.16, 0.23);
  double covering = 0.0;
  for (int i = 0; i < n.prod(); ++i) {
    const Eigen::Vector3d node =
        lo + 0.01 * Eigen::Vector3d(i % n.x(), i / n.x() % n.y(), i / (n.x() * n.y()));
    covering = std::max(covering, (batch_m.colwise() - node).colwise().norm().minCoeff());
  }
  EXPECT_LE(covering, separation + 1e-9);
  EXPECT_GT(separation, 0.03);
  // The visiting order is no longer than the order picked.
  double path = 0.0;
  for (Eigen::Index k = 1; k < batch_m.cols(); ++k)
    path += (batch_m.col(k) - batch_m.col(k - 1)).norm();
  EXPECT_NEAR(path, r.path_m, 1e-12);
}

// With known hyperparameters, the greedy pick is the brute-force best: every candidate's summed
// posterior variance at the parts recomputed from the reference with that candidate added.
TEST(PlanNext, GreedyPickIsTheBruteForceBest) {
  const SerialChain chain = ur5_with_sphere();
  PlanNextOptions o = small_options();
  const std::vector<PartPoint> parts = three_parts();
  const PlanNextResult first = plan_next(chain, parts, {}, o);
  ASSERT_TRUE(first.ok());
  MeasuredFiducials measured{batch_matrix(first), batch_matrix(first)};
  o.hyperparameters = known_hyperparameters();
  o.batch_size = 1;
  o.candidate_spacing_m = 0.02;  // fewer candidates for the brute force
  const PlanNextResult r = plan_next(chain, parts, measured, o);
  ASSERT_TRUE(r.ok());
  ASSERT_TRUE(r.has_model);
  ASSERT_EQ(r.locations.size(), 1u);
  const Points3 parts_m = parts_matrix(parts);
  const double now = reference_summed_variance(measured.robot_m, parts_m, r.model);
  const double picked_after =
      reference_summed_variance(joined(measured.robot_m, batch_matrix(r)), parts_m, r.model);
  // The result's own numbers: sum of sd^2 = latent variance + 3 nuggets^2 per part.
  double nuggets = 0.0;
  for (const KrigingDesignModel& m : r.model) nuggets += std::pow(m.hyperparameters.nugget_sd_m, 2);
  const auto n_parts = static_cast<double>(parts.size());
  EXPECT_NEAR(r.part_sd_now_m.squaredNorm(), now + n_parts * nuggets, 1e-9 * now);
  EXPECT_NEAR(now - picked_after, r.part_sd_now_m.squaredNorm() - r.part_sd_after_m.squaredNorm(),
              1e-9 * (now - picked_after));
  // No other lattice node does better.
  const Eigen::Vector3i n(6, 7, 3);
  const Eigen::Vector3d lo(0.40, -0.16, 0.235);
  int tried = 0;
  for (int i = 0; i < n.prod(); ++i) {
    const Eigen::Vector3d node =
        lo + 0.02 * Eigen::Vector3d(i % n.x(), i / n.x() % n.y(), i / (n.x() * n.y()));
    if ((measured.robot_m.colwise() - node).colwise().norm().minCoeff() < 0.01) continue;
    ++tried;
    const double after =
        reference_summed_variance(joined(measured.robot_m, node), parts_m, r.model);
    EXPECT_GE(after, picked_after - 1e-9 * (now - picked_after)) << node.transpose();
  }
  EXPECT_EQ(tried, r.n_candidates);
}

TEST(PlanNext, PredictedSdAfterTheBatchIsThePosteriorWithTheBatch) {
  SecondCall call;
  auto& [chain, o, parts, measured] = call;
  o.batch_size = 5;
  const PlanNextResult r = plan_next(chain, parts, measured, o);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.locations.size(), 5u);
  check_reachable(chain, r, o);
  const Points3 parts_m = parts_matrix(parts);
  const Points3 after_m = joined(measured.robot_m, batch_matrix(r));
  for (Eigen::Index p = 0; p < parts_m.cols(); ++p) {
    double now = 0.0;
    double after = 0.0;
    for (const KrigingDesignModel& m : r.model) {
      const double nugget2 = std::pow(m.hyperparameters.nugget_sd_m, 2);
      now += reference_covariance(measured.robot_m, parts_m.col(p), parts_m.col(p), m) + nugget2;
      after += reference_covariance(after_m, parts_m.col(p), parts_m.col(p), m) + nugget2;
    }
    EXPECT_NEAR(r.part_sd_now_m(p), std::sqrt(now), 1e-9 * std::sqrt(now));
    EXPECT_NEAR(r.part_sd_after_m(p), std::sqrt(after), 1e-9 * std::sqrt(after));
    EXPECT_LT(r.part_sd_after_m(p), r.part_sd_now_m(p));
  }
  EXPECT_NEAR(r.rms_sd_after_m, std::sqrt(r.part_sd_after_m.squaredNorm() / 3.0), 1e-15);
  // Labels continue the measured count.
  EXPECT_EQ(r.locations.size(), 5u);
  std::set<std::string> labels;
  for (const PlannedLocation& l : r.locations) labels.insert(l.point);
  EXPECT_EQ(labels, (std::set<std::string>{"n13", "n14", "n15", "n16", "n17"}));
}

TEST(PlanNext, StopsAtTheGoalOrTheBudget) {
  SecondCall call;
  auto& [chain, o, parts, measured] = call;
  PlanNextOptions easy = o;
  easy.goal_sd_m = 1.0;
  const PlanNextResult reached = plan_next(chain, parts, measured, easy);
  EXPECT_EQ(reached.decision, PlanNextDecision::kStop);
  EXPECT_EQ(reached.reason, "the goal is reached");
  EXPECT_TRUE(reached.locations.empty());
  PlanNextOptions spent = o;
  spent.budget = 12;
  const PlanNextResult budget = plan_next(chain, parts, measured, spent);
  EXPECT_EQ(budget.decision, PlanNextDecision::kStop);
  EXPECT_EQ(budget.reason, "the budget is spent");
  EXPECT_GT(budget.rms_sd_now_m, o.goal_sd_m);
  PlanNextOptions flat = o;
  flat.min_relative_gain = 0.99;
  const PlanNextResult small_gain = plan_next(chain, parts, measured, flat);
  EXPECT_EQ(small_gain.decision, PlanNextDecision::kStop);
  EXPECT_EQ(small_gain.reason,
            "another batch is expected to lower the predicted sd by less than 99 %");
  EXPECT_TRUE(small_gain.locations.empty());
  PlanNextOptions last = o;
  last.budget = 14;  // room for 2 of the batch of 4
  EXPECT_EQ(plan_next(chain, parts, measured, last).locations.size(), 2u);

  PlanNextOptions bad = o;
  bad.goal_sd_m = 0.0;
  EXPECT_THROW(plan_next(chain, parts, measured, bad), InputError);
  bad = o;
  bad.batch_size = 0;
  EXPECT_THROW(plan_next(chain, parts, measured, bad), InputError);
  EXPECT_THROW(plan_next(chain, {}, measured, o), InputError);
  MeasuredFiducials mismatched{measured.robot_m, measured.sensor_m.leftCols(3)};
  EXPECT_THROW(plan_next(chain, parts, mismatched, o), InputError);
  const PlanNextResult far = plan_next(chain, {{"far", {2.0, 0.0, 0.2}}}, {}, o);
  EXPECT_EQ(far.status, PlanStatus::kUnreachable);
  EXPECT_NE(far.message.find("far"), std::string::npos);
}

// Another correction's sd at the parts (the joint-space model's, say) is what the goal judges:
// "now" is its, "after" is not predicted and the 1 % rule is off, the batch is kriging's.
TEST(PlanNext, AnotherCorrectionsSdIsJudgedAgainstTheGoal) {
  SecondCall call;
  auto& [chain, o, parts, measured] = call;
  const PlanNextResult kriging = plan_next(chain, parts, measured, o);
  ASSERT_EQ(kriging.decision, PlanNextDecision::kContinue);
  EXPECT_EQ(kriging.sd_method, "kriging");

  const Eigen::Vector3d own_sd_m(0.03e-3, 0.04e-3, 0.05e-3);
  std::vector<PartPlan> seen;
  PlanNextOptions with = o;
  with.goal_sd_m = 0.01e-3;  // below both: the batch is planned
  with.correction_sd = [&](const std::vector<PartPlan>& p) {
    seen = p;
    return CorrectionSd{own_sd_m, "joint", ""};
  };
  const PlanNextResult r = plan_next(chain, parts, measured, with);
  ASSERT_EQ(r.decision, PlanNextDecision::kContinue);
  EXPECT_EQ(r.sd_method, "joint");
  ASSERT_EQ(seen.size(), 3u);  // the parts with their joints, input order
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(seen[i].name, parts[i].name);
    EXPECT_TRUE(seen[i].reachable);
    EXPECT_EQ(seen[i].q_rad.size(), 6);
  }
  EXPECT_EQ(r.part_sd_now_m, Eigen::VectorXd(own_sd_m));
  EXPECT_NEAR(r.rms_sd_now_m, std::sqrt(own_sd_m.squaredNorm() / 3.0), 1e-18);
  ASSERT_EQ(r.locations.size(), kriging.locations.size());
  for (std::size_t k = 0; k < r.locations.size(); ++k)
    EXPECT_EQ(r.locations[k].robot_m, kriging.locations[k].robot_m);
  ASSERT_EQ(r.part_sd_after_m.size(), 3);
  EXPECT_TRUE(r.part_sd_after_m.array().isNaN().all());
  EXPECT_TRUE(std::isnan(r.rms_sd_after_m));
  PlanNextOptions flat = with;
  flat.min_relative_gain = 0.99;  // stops kriging's loop (StopsAtTheGoalOrTheBudget), not this
  EXPECT_EQ(plan_next(chain, parts, measured, flat).decision, PlanNextDecision::kContinue);

  // The goal between the two predictions: kriging's goes on, the other correction's stops.
  PlanNextOptions between = with;
  between.goal_sd_m = 0.5 * (r.rms_sd_now_m + kriging.rms_sd_now_m);
  ASSERT_LT(r.rms_sd_now_m, between.goal_sd_m);
  ASSERT_GT(kriging.rms_sd_now_m, between.goal_sd_m);
  const PlanNextResult stop = plan_next(chain, parts, measured, between);
  EXPECT_EQ(stop.decision, PlanNextDecision::kStop);
  EXPECT_EQ(stop.reason, "the goal is reached");
  between.correction_sd = {};
  EXPECT_EQ(plan_next(chain, parts, measured, between).decision, PlanNextDecision::kContinue);

  // No sd yet (too few fiducials for it): kriging's, with the reason.
  PlanNextOptions none = o;
  none.correction_sd = [](const std::vector<PartPlan>&) {
    return CorrectionSd{std::nullopt, "joint", "too few fiducials"};
  };
  const PlanNextResult fallback = plan_next(chain, parts, measured, none);
  EXPECT_EQ(fallback.sd_method, "kriging");
  EXPECT_EQ(fallback.sd_note, "too few fiducials");
  EXPECT_EQ(fallback.part_sd_now_m, kriging.part_sd_now_m);

  // A wrong count or a value that is not a finite sd is refused.
  PlanNextOptions bad = o;
  bad.correction_sd = [](const std::vector<PartPlan>&) {
    return CorrectionSd{Eigen::VectorXd::Constant(2, 1e-4), "joint", ""};
  };
  EXPECT_THROW(plan_next(chain, parts, measured, bad), InputError);
  bad.correction_sd = [](const std::vector<PartPlan>&) {
    return CorrectionSd{Eigen::Vector3d(1e-4, std::nan(""), 1e-4), "joint", ""};
  };
  EXPECT_THROW(plan_next(chain, parts, measured, bad), InputError);

  // Before any model (the space-filling start) the hook is not asked.
  PlanNextOptions start = small_options();
  bool asked = false;
  start.correction_sd = [&](const std::vector<PartPlan>&) {
    asked = true;
    return CorrectionSd{};
  };
  EXPECT_TRUE(plan_next(chain, parts, {}, start).space_filling);
  EXPECT_FALSE(asked);
}

// A goal as a multiple of the noise floor sqrt(3 (sigma_rep^2 + sigma_opt^2 / K)): unknown before
// the noise is (no batch stops on it), then the multiple of the floor, and a stop once the
// predicted sd is below it.
TEST(PlanNext, GoalAsAMultipleOfTheNoiseFloor) {
  const SerialChain chain = ur5_with_sphere();
  PlanNextOptions o = small_options();
  o.goal_sd_m = 0.0;
  o.goal_floor_multiple = 3.0;
  o.sigma_rep_m = 0.04e-3;
  const std::vector<PartPoint> parts = three_parts();
  const PlanNextResult first = plan_next(chain, parts, {}, o);
  EXPECT_TRUE(std::isnan(first.noise_floor_m));
  EXPECT_TRUE(std::isnan(first.goal_sd_m));
  EXPECT_EQ(first.decision, PlanNextDecision::kContinue);
  EXPECT_EQ(first.locations.size(), 12u);
  EXPECT_NE(first.reason.find("noise floor, and so the goal, is not known yet"), std::string::npos)
      << first.reason;

  MeasuredFiducials measured{batch_matrix(first), batch_matrix(first)};
  o.hyperparameters = known_hyperparameters();
  // Known hyperparameters: the nugget is theirs; only the goal depends on noise_sd_m.
  const PlanNextResult unknown = plan_next(chain, parts, measured, o);
  EXPECT_EQ(unknown.decision, PlanNextDecision::kContinue);
  EXPECT_FALSE(unknown.locations.empty());
  o.noise_sd_m = 0.03e-3;
  const PlanNextResult known = plan_next(chain, parts, measured, o);
  // sqrt(3 (0.04^2 + 0.03^2)) = sqrt(3) 0.05 mm.
  EXPECT_NEAR(known.noise_floor_m, std::sqrt(3.0) * 0.05e-3, 1e-15);
  EXPECT_NEAR(known.goal_sd_m, 3.0 * std::sqrt(3.0) * 0.05e-3, 1e-15);
  // The goal is the sd one would give: the same decision and batch as goal_sd_m.
  PlanNextOptions as_sd = o;
  as_sd.goal_floor_multiple.reset();
  as_sd.goal_sd_m = known.goal_sd_m;
  const PlanNextResult same = plan_next(chain, parts, measured, as_sd);
  EXPECT_EQ(known.decision, same.decision);
  EXPECT_EQ(known.reason, same.reason);
  ASSERT_EQ(known.locations.size(), same.locations.size());
  for (std::size_t k = 0; k < known.locations.size(); ++k) {
    EXPECT_EQ(known.locations[k].robot_m, same.locations[k].robot_m);
  }
  // A multiple above predicted sd / floor stops at once.
  o.goal_floor_multiple = 1.01 * known.rms_sd_now_m / known.noise_floor_m;
  const PlanNextResult reached = plan_next(chain, parts, measured, o);
  EXPECT_EQ(reached.decision, PlanNextDecision::kStop);
  EXPECT_EQ(reached.reason, "the goal is reached");
  o.goal_floor_multiple = 0.99 * known.rms_sd_now_m / known.noise_floor_m;
  EXPECT_EQ(plan_next(chain, parts, measured, o).decision, PlanNextDecision::kContinue);

  PlanNextOptions both = o;
  both.goal_sd_m = 0.1e-3;
  EXPECT_THROW(plan_next(chain, parts, measured, both), InputError);
  PlanNextOptions zero = o;
  zero.goal_floor_multiple = 0.0;
  EXPECT_THROW(plan_next(chain, parts, measured, zero), InputError);
}

// Candidate positions are lattice values in millimetres: m_to_mm of each is exactly the node
// origin + k spacing (the parts' box 400..500 mm wide, centred, 10 mm spacing: whole mm).
TEST(PlanNext, CandidatePositionsAreExactLatticeMillimetres) {
  const SerialChain chain = ur5_with_sphere();
  const PlanNextResult first = plan_next(chain, three_parts(), {}, small_options());
  ASSERT_FALSE(first.locations.empty());
  for (const PlannedLocation& l : first.locations) {
    for (int i = 0; i < 3; ++i) {
      const double mm = l.robot_m(i) * 1000.0;
      EXPECT_EQ(mm, std::round(mm)) << l.point << " axis " << i;
    }
  }
}

// A work volume as part points: the lattice is centred in the box (equal margins), x fastest,
// named v1..; a degenerate axis gives one node; bad boxes and spacings are refused.
TEST(VolumePartPoints, LatticeCentredInTheBox) {
  const std::vector<PartPoint> parts =
      volume_part_points({0.40, -0.15, 0.25}, {0.52, -0.05, 0.25}, 0.05);
  // x: 120 mm -> 3 nodes, 10 mm margins; y: 100 mm -> 3 nodes; z: 0 mm -> 1 node.
  ASSERT_EQ(parts.size(), 9u);
  EXPECT_EQ(parts.front().name, "v1");
  EXPECT_EQ(parts.back().name, "v9");
  EXPECT_EIGEN_NEAR(parts[0].robot_m, Eigen::Vector3d(0.41, -0.15, 0.25), 1e-12);
  EXPECT_EIGEN_NEAR(parts[1].robot_m, Eigen::Vector3d(0.46, -0.15, 0.25), 1e-12);
  EXPECT_EIGEN_NEAR(parts[3].robot_m, Eigen::Vector3d(0.41, -0.10, 0.25), 1e-12);
  EXPECT_EIGEN_NEAR(parts[8].robot_m, Eigen::Vector3d(0.51, -0.05, 0.25), 1e-12);
  // A 200 mm extent at 50 mm keeps both ends despite rounding (5 nodes).
  EXPECT_EQ(volume_part_points({0.4, 0.0, 0.2}, {0.6, 0.0, 0.2}, 0.05).size(), 5u);
  EXPECT_THROW((void)volume_part_points({0.5, 0, 0}, {0.4, 0, 0}, 0.05), InputError);
  EXPECT_THROW((void)volume_part_points({0, 0, 0}, {0.1, 0.1, 0.1}, 0.0), InputError);
  EXPECT_THROW((void)volume_part_points({0, 0, 0}, {0.1, 0.1, 0.1}, std::nan("")), InputError);
  EXPECT_THROW((void)volume_part_points({0, 0, 0}, {1.0, 1.0, 1.0}, 0.001), InputError);
}

}  // namespace
}  // namespace vrreg::planning
