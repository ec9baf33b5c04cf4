// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/plan.hpp"

#include <cmath>
#include <sstream>
#include <unordered_set>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/planning/cube_tour.hpp"
#include "vrreg/planning/serpentine.hpp"

namespace vrreg::planning {
namespace {

constexpr std::size_t kNamedInMessage = 5;

// Joints of every node of a cube, index ix + n (iy + n iz); the part's joints are in PartPlan.
using CubeJoints = std::vector<JointChoice>;

std::string fiducial_label(const std::string& part, const Eigen::Vector3i& index) {
  return part + ".f" + std::to_string(index.x()) + "-" + std::to_string(index.y()) + "-" +
         std::to_string(index.z());
}

void check_parts(const std::vector<PartPoint>& parts) {
  VRREG_THROW_UNLESS(!parts.empty(), "plan: no part points");
  std::unordered_set<std::string> names;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const PartPoint& p = parts[i];
    VRREG_THROW_UNLESS(!p.name.empty(), "plan: part point " << i + 1 << " has no name");
    VRREG_THROW_UNLESS(p.robot_m.allFinite(),
                       "plan: part point '" << p.name << "' has a non-finite position");
    VRREG_THROW_UNLESS(names.insert(p.name).second,
                       "plan: two part points are named '" << p.name << "'");
  }
}

// Labels must be unique across the plan (a part named "A.f0-0-0" would clash with A's fiducial).
void check_labels(const std::vector<PartPoint>& parts, const CubeGeometry& cube) {
  std::unordered_set<std::string> labels;
  for (const PartPoint& p : parts) labels.insert(p.name);
  const int n = cube.nodes_per_axis;
  for (const PartPoint& p : parts) {
    for (int iz = 0; iz < n; ++iz) {
      for (int iy = 0; iy < n; ++iy) {
        for (int ix = 0; ix < n; ++ix) {
          const std::string label = fiducial_label(p.name, {ix, iy, iz});
          VRREG_THROW_UNLESS(
              labels.insert(label).second,
              "plan: fiducial label '" << label << "' is also the name of a part point");
        }
      }
    }
  }
}

int node_column(const Eigen::Vector3i& index, int n) {
  return index.x() + n * (index.y() + n * index.z());
}

// IK for one part point and its cube; records unreachable locations.
CubeJoints solve_cube(const kinematics::SerialChain& chain, const PartPoint& part, int index,
                      const PlanOptions& options, const CubeGeometry& cube, PartPlan& plan,
                      std::vector<UnreachableLocation>& unreachable) {
  const JointChoice at_part = part_joints(chain, part.robot_m, options.arm);
  if (!at_part.ok()) {
    unreachable.push_back({part.name,
                           std::string(kinematics::to_string(at_part.status)) + ": " +
                               at_part.message + " (its fiducials were not tried)",
                           index});
    return {};
  }
  plan.reachable = true;
  plan.q_rad = at_part.q_rad;
  plan.config = at_part.config;
  const Points3 nodes = cube_nodes(cube, part.robot_m);
  CubeJoints joints(static_cast<std::size_t>(nodes.cols()));
  const int n = cube.nodes_per_axis;
  for (Eigen::Index c = 0; c < nodes.cols(); ++c) {
    const JointChoice choice = nearest_joints(chain, nodes.col(c), at_part.q_rad, options.arm);
    if (!choice.ok()) {
      const auto k = static_cast<int>(c);
      unreachable.push_back(
          {fiducial_label(part.name, {k % n, (k / n) % n, k / (n * n)}),
           std::string(kinematics::to_string(choice.status)) + ": " + choice.message, index});
      continue;
    }
    joints[static_cast<std::size_t>(c)] = choice;
    if (!(choice.config == at_part.config)) ++plan.n_other_config;
    plan.max_joint_distance_rad = std::max(plan.max_joint_distance_rad, choice.distance_rad);
  }
  return joints;
}

std::string unreachable_message(const std::vector<UnreachableLocation>& unreachable,
                                const PlanOptions& options, long long total) {
  std::ostringstream out;
  out << unreachable.size() << " of " << total
      << " planned locations cannot be reached with the given tool orientation";
  if (options.arm.home_q_rad) out << " and home joints";
  out << ": ";
  for (std::size_t i = 0; i < unreachable.size() && i < kNamedInMessage; ++i) {
    out << (i > 0 ? "; " : "") << unreachable[i].point << " (" << unreachable[i].reason << ")";
  }
  if (unreachable.size() > kNamedInMessage) {
    out << "; and " << unreachable.size() - kNamedInMessage << " more";
  }
  return out.str();
}

void find_overlaps(const std::vector<PartPoint>& parts, const CubeGeometry& cube,
                   PlanResult& result) {
  for (std::size_t i = 0; i < parts.size(); ++i) {
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      const double gap = (parts[i].robot_m - parts[j].robot_m).cwiseAbs().maxCoeff();
      if (gap <= 2.0 * cube.halfwidth_m) {
        result.overlapping.push_back({static_cast<int>(i), static_cast<int>(j)});
      }
    }
  }
}

}  // namespace

const char* to_string(PlanStatus status) {
  return status == PlanStatus::kOk ? "ok" : "unreachable";
}

void PlanOptions::validate(const kinematics::SerialChain& chain) const {
  VRREG_THROW_UNLESS(std::isfinite(sigma_noise_m) && sigma_noise_m > 0.0,
                     "plan: sigma_noise must be finite and positive, got "
                         << units::m_to_mm(sigma_noise_m) << " mm");
  VRREG_THROW_UNLESS(max_locations > 0, "plan: max_locations must be positive");
  (void)cube_geometry(halfwidth_m, spacing_m);
  arm.validate(chain);
  approach.validate(chain);
}

PlanResult make_plan(const kinematics::SerialChain& chain, const std::vector<PartPoint>& parts,
                     const PlanOptions& options) {
  options.validate(chain);
  check_parts(parts);
  PlanResult result;
  result.cube = cube_geometry(options.halfwidth_m, options.spacing_m);
  const CubeGeometry& cube = result.cube;
  result.dmin = check_dmin(cube.d_min_m(), options.sigma_noise_m, options.force);
  const auto m = static_cast<long long>(parts.size());
  const long long total = m * (cube.n_nodes() + 1);
  VRREG_THROW_UNLESS(total <= options.max_locations,
                     "plan: " << m << " part points x " << cube.n_nodes() + 1
                              << " locations per cube = " << total << " locations, more than "
                              << options.max_locations
                              << "; use a larger spacing or a smaller half-width");
  check_labels(parts, cube);
  find_overlaps(parts, cube, result);

  std::vector<CubeJoints> joints(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    PartPlan& plan = result.parts.emplace_back();
    plan.name = parts[i].name;
    plan.robot_m = parts[i].robot_m;
    plan.n_fiducials = cube.n_nodes();
    plan.d_min_m = cube.d_min_m();
    plan.d_max_m = cube.d_max_m();
    joints[i] =
        solve_cube(chain, parts[i], static_cast<int>(i), options, cube, plan, result.unreachable);
  }
  if (!result.unreachable.empty()) {
    result.status = PlanStatus::kUnreachable;
    result.message = unreachable_message(result.unreachable, options, total);
    return result;
  }

  // Visiting order: cube sequence and serpentine variants, then each cube's serpentine.
  const int n = cube.nodes_per_axis;
  Points3 centres(3, static_cast<Eigen::Index>(m));
  for (std::size_t i = 0; i < parts.size(); ++i) {
    centres.col(static_cast<Eigen::Index>(i)) = parts[i].robot_m;
  }
  Points3 entry(3, kSerpentineVariants);
  Points3 exit(3, kSerpentineVariants);
  for (int v = 0; v < kSerpentineVariants; ++v) {
    const auto ends = serpentine_ends(n, serpentine_variant(v));
    entry.col(v) = cube_node(cube, Eigen::Vector3d::Zero(), ends[0]);
    exit.col(v) = cube_node(cube, Eigen::Vector3d::Zero(), ends[1]);
  }
  const CubeTour tour = plan_cube_tour(centres, entry, exit);
  std::vector<int> input_order(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) input_order[i] = static_cast<int>(i);
  result.between_cubes_m = tour.between_cubes_m;
  result.naive_between_cubes_m =
      between_cube_travel_m(centres, entry, exit, input_order, std::vector<int>(parts.size(), 0));

  result.locations.reserve(static_cast<std::size_t>(total));
  for (std::size_t k = 0; k < tour.order.size(); ++k) {
    const auto i = static_cast<std::size_t>(tour.order[k]);
    PartPlan& plan = result.parts[i];
    plan.visit_rank = static_cast<int>(k);
    std::vector<Eigen::Vector3i> path = serpentine(n, serpentine_variant(tour.variant[k]));
    insert_centre(path, n);
    for (std::size_t step = 0; step < path.size(); ++step) {
      const Eigen::Vector3i& index = path[step];
      PlannedLocation& loc = result.locations.emplace_back();
      loc.part = static_cast<int>(i);
      loc.grid_index = index;
      if (index == kCentreIndex) {
        loc.point = plan.name;
        loc.role = Role::kTarget;
        loc.robot_m = plan.robot_m;
        loc.q_rad = plan.q_rad;
        loc.config = plan.config;
      } else {
        loc.point = fiducial_label(plan.name, index);
        loc.role = Role::kFiducial;
        loc.robot_m = cube_node(cube, plan.robot_m, index);
        const JointChoice& choice = joints[i][static_cast<std::size_t>(node_column(index, n))];
        loc.q_rad = choice.q_rad;
        loc.config = choice.config;
        loc.joint_distance_rad = choice.distance_rad;
      }
      if (step > 0) {
        const std::size_t last = result.locations.size() - 1;
        result.within_cubes_m +=
            (result.locations[last].robot_m - result.locations[last - 1].robot_m).norm();
      }
    }
  }
  add_approach_vias(chain, result, options.approach);
  return result;
}

}  // namespace vrreg::planning
