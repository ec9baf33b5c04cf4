// SPDX-License-Identifier: Apache-2.0
// What lost motion (gear backlash) costs and what correcting it gives (docs/joint-space-model.md,
// "Lost motion"): simulated UR5 cells with per-joint lost motion, alone (backlash) or with the
// test bed's transmission error, gravity sag and thermal growth (mixed), and the same cells
// without it (none); fiducials on a 25 mm grid, a 50 mm grid or 700 scattered points, visited
// along a raster; 60 targets inside, visited afterwards in random order (so each arrives from
// directions its neighbours did not). Per cell: `auto` with the lost-motion term (its default),
// `auto` without it, and the metrology practice (every location approached from one direction,
// auto without the term); RMS_T over the noise floor and the RMS of TRE / predicted sd.
//
//   vrreg_lost_motion_study [FIRST_SEED [SEEDS]]            (default 1 3)
//
// STUDY_PHYSICS="backlash mixed none" and STUDY_LAYOUTS="grid thin scattered" pick cells;
// STUDY_DETAIL=1 prints whether the term entered and its cross-validated RMS with and without.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "vrreg/core/units.hpp"
#include "vrreg/experiments/beyond_paper.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/kinematics/ur_ik.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"
#include "vrreg/planning/approach.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace {

using vrreg::MeasurementSet;
using vrreg::Role;
namespace sim = vrreg::simulation;

constexpr double kArcmin = M_PI / (180.0 * 60.0);

std::vector<std::string> words(const char* env, const char* fallback) {
  const char* v = std::getenv(env);
  std::istringstream in(v != nullptr ? v : fallback);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// The plays: 0.4-0.8 arc-min on joints 1, 4, 5, 6; 0.15-0.2 on the gravity-preloaded 2, 3.
std::vector<double> plays_rad() {
  return {0.8 * kArcmin, 0.2 * kArcmin, 0.15 * kArcmin, 0.7 * kArcmin, 0.6 * kArcmin,
          0.4 * kArcmin};
}

sim::TestbedErrorModel physics(const sim::Testbed& ur5, const std::string& name) {
  sim::TestbedErrorModel e = ur5.default_errors;
  e.tracker.rigid_body_radius_m = 0.0;
  if (name == "mixed") {
    e.robot.lost_motion_rad = plays_rad();
    // Gravity sag: the UR5's link masses (datasheet) on joints of 1e5 N m / rad (about 0.2 mm
    // at the TCP), and thermal growth of 3 K of aluminium.
    e.robot.compliance = true;
    e.robot.link_mass_kg = {3.7, 8.393, 2.275, 1.219, 1.219, 0.1879};
    e.robot.joint_stiffness_nm_per_rad = {1e5, 1e5, 1e5, 3e4, 3e4, 3e4};
    e.robot.payload_kg = 0.2;
    e.robot.link_growth = 3.0 * 2.3e-5;
    return e;
  }
  e.robot.transmission_amplitude_rad.clear();
  e.robot.transmission_period_rad.clear();
  if (name == "backlash") e.robot.lost_motion_rad = plays_rad();
  return e;
}

// The cell's box: the UR5 volume's half with x <= 125 mm of its 250 (A1's nodes there).
struct Box {
  Eigen::Vector3d lo, hi;
};

Box cell_box(const sim::Testbed& ur5) {
  const Eigen::Vector3d half(0.125, 0.150, 0.100);
  Box b{ur5.volume_centre_m - half, ur5.volume_centre_m + half};
  b.hi.x() = b.lo.x() + 0.125;
  return b;
}

// Raster order (z layers, y rows, x serpentine) of points binned at `step_m`.
void raster_sort(std::vector<Eigen::Vector3d>& p, const Box& box, double step_m) {
  const auto key = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d c = (x - box.lo) / step_m;
    const long k = std::lround(c.z()), j = std::lround(c.y());
    const double i = ((k * 1000 + j) % 2 == 0) ? c.x() : -c.x();
    return std::make_tuple(k, (k % 2 == 0) ? j : -j, i);
  };
  std::stable_sort(p.begin(), p.end(),
                   [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return key(a) < key(b); });
}

std::vector<Eigen::Vector3d> fiducial_points(const std::string& layout, const Box& box,
                                             std::mt19937_64& rng) {
  std::vector<Eigen::Vector3d> p;
  if (layout == "scattered") {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 700; ++k) {
      p.emplace_back(box.lo + (box.hi - box.lo).cwiseProduct(Eigen::Vector3d(u(rng), u(rng), u(rng))));
    }
    raster_sort(p, box, 0.025);
    return p;
  }
  const double step = layout == "thin" ? 0.050 : 0.025;
  const Eigen::Vector3i n = ((box.hi - box.lo) / step).array().round().cast<int>() + 1;
  for (int k = 0; k < n.z(); ++k) {
    for (int jj = 0; jj < n.y(); ++jj) {
      const int j = k % 2 == 0 ? jj : n.y() - 1 - jj;
      for (int ii = 0; ii < n.x(); ++ii) {
        const int i = (k * n.y() + jj) % 2 == 0 ? ii : n.x() - 1 - ii;
        p.push_back(box.lo + step * Eigen::Vector3d(i, j, k));
      }
    }
  }
  return p;
}

std::vector<sim::CommandedLocation> commanded(const sim::Testbed& ur5,
                                              const std::vector<Eigen::Vector3d>& fiducials,
                                              const std::vector<Eigen::Vector3d>& targets,
                                              bool one_direction) {
  std::vector<sim::CommandedLocation> plan;
  vrreg::kinematics::JointVector q = ur5.home_q_rad;
  vrreg::planning::ApproachOptions approach;
  approach.direction = vrreg::kinematics::JointVector::Ones(ur5.nominal.n_joints());
  const auto add = [&](const Eigen::Vector3d& p, Role role, std::size_t k) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = ur5.tcp_rotation;
    T.translation() = p;
    const vrreg::kinematics::IkResult ik =
        vrreg::kinematics::ur_inverse_kinematics_nearest(ur5.nominal, T, q);
    if (ik.solutions.empty()) throw std::runtime_error("unreachable cell point");
    q = ik.solutions.front().q_rad;
    sim::CommandedLocation c;
    c.point = (role == Role::kFiducial ? "f" : "t") + std::to_string(k);
    c.role = role;
    c.robot_m = p;
    c.q_rad = q;
    if (one_direction) c.via_q_rad = vrreg::planning::approach_via(ur5.nominal, q, approach);
    plan.push_back(c);
  };
  for (std::size_t k = 0; k < fiducials.size(); ++k) add(fiducials[k], Role::kFiducial, k);
  for (std::size_t k = 0; k < targets.size(); ++k) add(targets[k], Role::kTarget, k);
  return plan;
}

struct Figures {
  double floor_multiple = NAN;  // RMS_T / noise floor
  double tre_over_sd = NAN;     // RMS of TRE / predicted sd
  std::string chosen;
  std::string term;  // whether the lost-motion term entered, and its cross-validation
};

Figures correct(const MeasurementSet& measured, double floor_m, const sim::Testbed& ur5,
                vrreg::LostMotionMode lost_motion) {
  vrreg::RegisterOptions r;
  r.interpolation.method = vrreg::InterpolationMethod::kAuto;
  r.lost_motion = lost_motion;
  r.robot = ur5.nominal;
  MeasurementSet fiducials = measured;
  fiducials.locations.clear();
  MeasurementSet targets = fiducials;
  for (const vrreg::Location& l : measured.locations) {
    (l.role == Role::kFiducial ? fiducials : targets).locations.push_back(l);
  }
  const vrreg::RegisterResult reg = vrreg::register_fiducials(fiducials, r);
  vrreg::EvaluateOptions e;
  e.robot = ur5.nominal;
  const vrreg::EvaluateResult ev = vrreg::evaluate(reg.model, targets, e);
  Figures f;
  f.floor_multiple = ev.summary.cor_rms_t_m / floor_m;
  f.tre_over_sd = ev.calibration.n > 0 ? ev.calibration.rms_ratio : NAN;
  f.chosen = vrreg::to_string(ev.interpolation.method);
  if (reg.model.corrector && reg.model.corrector->lost_motion())
    f.term = reg.model.corrector->lost_motion()->reason;
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  const int first_seed = argc > 1 ? std::atoi(argv[1]) : 1;
  const int n_seeds = argc > 2 ? std::atoi(argv[2]) : 3;
  const sim::Testbed ur5 = sim::ur5_testbed();
  const Box box = cell_box(ur5);
  std::printf("%-9s %-9s %4s | %-22s | %-10s | %-10s\n", "physics", "layout", "seed",
              "auto (term): x floor, TRE/sd", "auto, no term", "one direction");
  for (const std::string& phys : words("STUDY_PHYSICS", "backlash mixed none")) {
    for (const std::string& layout : words("STUDY_LAYOUTS", "grid thin scattered")) {
      for (int s = first_seed; s < first_seed + n_seeds; ++s) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(1000 + s));
        const std::vector<Eigen::Vector3d> fid = fiducial_points(layout, box, rng);
        std::vector<Eigen::Vector3d> tgt;
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const Eigen::Vector3d margin = Eigen::Vector3d::Constant(0.0125);
        for (int k = 0; k < 60; ++k) {
          tgt.emplace_back(box.lo + margin +
                           (box.hi - box.lo - 2.0 * margin)
                               .cwiseProduct(Eigen::Vector3d(u(rng), u(rng), u(rng))));
        }
        const sim::TestbedErrorModel errors = physics(ur5, phys);
        Figures fig[3];
        for (const bool one_direction : {false, true}) {
          const std::vector<sim::CommandedLocation> plan = commanded(ur5, fid, tgt, one_direction);
          const MeasurementSet measured = vrreg::experiments::to_measurement_set(
              sim::simulate_plan(ur5, plan, {static_cast<std::uint64_t>(s), errors}));
          const MeasurementSet noise_free = vrreg::experiments::to_measurement_set(sim::simulate_plan(
              ur5, plan, {static_cast<std::uint64_t>(s), vrreg::experiments::without_noise(errors)}));
          const std::vector<std::size_t> rows = measured.select(Role::kTarget);
          const double floor_m = vrreg::experiments::noise_floor_m(measured, noise_free, rows);
          if (one_direction) {
            fig[2] = correct(measured, floor_m, ur5, vrreg::LostMotionMode::kOff);
          } else {
            fig[0] = correct(measured, floor_m, ur5, vrreg::LostMotionMode::kAuto);
            fig[1] = correct(measured, floor_m, ur5, vrreg::LostMotionMode::kOff);
          }
        }
        std::printf("%-9s %-9s %4d | %5.2f %5.2f %-10s | %5.2f %-4.4s | %5.2f %-4.4s\n",
                    phys.c_str(), layout.c_str(), s, fig[0].floor_multiple, fig[0].tre_over_sd,
                    fig[0].chosen.c_str(), fig[1].floor_multiple, fig[1].chosen.c_str(),
                    fig[2].floor_multiple, fig[2].chosen.c_str());
        if (std::getenv("STUDY_DETAIL") != nullptr) std::printf("    term: %s\n", fig[0].term.c_str());
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
