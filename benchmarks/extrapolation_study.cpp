// SPDX-License-Identifier: Apache-2.0
// How honest an extrapolated correction's sd is (docs/uncertainty.md, "Extrapolation"): every
// method fitted on simulated lattices (sizes, spacings, repeat counts) under each far-field
// physics, asked about targets 1, 10 and 100 lattice sizes beyond the lattice with
// CorrectionQuery::extrapolate; prints the RMS of TRE/sd per physics, method and distance.
//
//   vrreg_extrapolation_study [FIRST_SEED [SEEDS]]      (default 1 5: the calibration seeds)
//   vrreg_extrapolation_study rail [FIRST_SEED [SEEDS]] the joint model's gaps on rail cells
//
// STUDY_PHYSICS="ur5 lwr4" runs only the physics named; STUDY_DETAIL=1 prints, per cell of the
// table, the RMS TRE, sd and uncorrected TRE [mm] too (and the rail models' descriptions).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "vrreg/correction/corrector.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/registration/rigid.hpp"
#include "vrreg/simulation/far_field_cells.hpp"
#include "vrreg/simulation/rail_cell.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace {

using vrreg::InterpolationMethod;
using vrreg::simulation::FarPhysics;

struct Layout {
  int nodes;
  double spacing_m;
  int repeats;
};

struct Sum {
  double z2 = 0.0;
  double tre2 = 0.0;
  double sd2 = 0.0;
  double unc2 = 0.0;
  int n = 0;
  int flagged = 0;
  void add(double tre, double sd, double unc) {
    z2 += tre * tre / (sd * sd);
    tre2 += tre * tre;
    sd2 += sd * sd;
    unc2 += unc * unc;
    ++n;
  }
  [[nodiscard]] double rms() const { return n > 0 ? std::sqrt(z2 / n) : NAN; }
};

// (physics, method, distance) -> sums
using Table = std::map<std::tuple<std::string, std::string, double>, Sum>;

void run_cell(const vrreg::simulation::FarFieldCell& cell, FarPhysics physics,
              const Layout& layout, Table& table) {
  const vrreg::RegistrationResult reg =
      vrreg::register_rigid(cell.fiducials_sensor_m, cell.fiducials_robot_m);
  const vrreg::Points3 corrections = vrreg::fiducial_corrections(
      reg.T_robot_sensor, cell.fiducials_sensor_m, cell.fiducials_robot_m);
  vrreg::CorrectorData data = vrreg::CorrectorData::of(reg.T_robot_sensor, cell.fiducials_sensor_m,
                                                       cell.fiducials_robot_m, corrections);
  if (layout.repeats > 1) data.noise_sd_m = cell.noise_sd_m;
  const bool robot = !cell.robot.empty();
  if (robot) {
    data.joints_rad = cell.fiducials_q_rad;
    data.robot = vrreg::simulation::testbed_by_name(cell.robot).nominal;
  }
  std::vector<InterpolationMethod> methods{
      InterpolationMethod::kGrid,     InterpolationMethod::kScattered, InterpolationMethod::kOctuplet,
      InterpolationMethod::kTrilinear, InterpolationMethod::kKriging,  InterpolationMethod::kRbf};
  if (robot) methods.push_back(InterpolationMethod::kJoint);
  for (const InterpolationMethod method : methods) {
    vrreg::CorrectorOptions options;
    options.interpolation.method = method;
    options.interpolation.cube_edge_m = layout.spacing_m;
    std::string why;
    const std::optional<vrreg::Corrector> corrector = vrreg::Corrector::try_fit(data, options, why);
    if (!corrector) continue;
    const Eigen::MatrixXd no_joints(0, 0);
    vrreg::CorrectionQuery query(cell.targets_sensor_m, cell.targets_robot_m,
                                 method == InterpolationMethod::kJoint ? cell.targets_q_rad : no_joints);
    query.extrapolate = true;
    const vrreg::TargetCorrection c = corrector->correct(query);
    for (Eigen::Index t = 0; t < cell.targets_robot_m.cols(); ++t) {
      Sum& s = table[{to_string(physics), to_string(method),
                      cell.target_distance[static_cast<std::size_t>(t)]}];
      if (c.stencils[static_cast<std::size_t>(t)].status != vrreg::StencilStatus::kExtrapolated) {
        ++s.flagged;
        continue;
      }
      const double tre_m = (c.corrected_robot_m.col(t) - cell.targets_robot_m.col(t)).norm();
      s.add(tre_m, c.predicted_sd_m(t),
            (c.uncorrected_robot_m.col(t) - cell.targets_robot_m.col(t)).norm());
    }
  }
}

// The rail cells (simulation/rail_cell.hpp): the joint model's targets between carriage
// positions, plain and with extrapolate; RMS of TRE/sd and how many were flagged.
void rail_study(std::uint64_t first, std::uint64_t seeds) {
  struct Case {
    const char* name;
    std::vector<double> stations_m;
    double ripple_m;
  };
  const std::vector<Case> cases{{"3 positions, 0.15 mm ripple", {0.7, 1.0, 1.3}, 0.15e-3},
                                {"5 positions, 0.15 mm ripple", {0.7, 0.85, 1.0, 1.15, 1.3}, 0.15e-3},
                                {"3 positions, no ripple", {0.7, 1.0, 1.3}, 0.0}};
  std::printf("rail cells, seeds %llu-%llu: RMS TRE, RMS of TRE/sd (ok targets; n flagged), "
              "with extrapolate (all targets)\n",
              static_cast<unsigned long long>(first),
              static_cast<unsigned long long>(first + seeds - 1));
  for (const Case& c : cases) {
    Sum ok;
    Sum all;
    for (std::uint64_t seed = first; seed < first + seeds; ++seed) {
      vrreg::simulation::RailCellOptions o;
      o.stations_m = c.stations_m;
      o.ripple_amplitude_m = c.ripple_m;
      o.seed = seed;
      const vrreg::simulation::RailCell cell = vrreg::simulation::rail_cell(o);
      const vrreg::RegistrationResult reg =
          vrreg::register_rigid(cell.fiducials_sensor_m, cell.fiducials_robot_m);
      vrreg::CorrectorData data = vrreg::CorrectorData::of(
          reg.T_robot_sensor, cell.fiducials_sensor_m, cell.fiducials_robot_m,
          vrreg::fiducial_corrections(reg.T_robot_sensor, cell.fiducials_sensor_m,
                                      cell.fiducials_robot_m));
      data.joints_rad = cell.fiducials_q_rad;
      data.robot = cell.robot;
      data.noise_sd_m = cell.noise_sd_m;
      vrreg::CorrectorOptions options;
      options.interpolation.method = InterpolationMethod::kJoint;
      const vrreg::Corrector corrector = vrreg::Corrector::fit(data, options);
      if (std::getenv("STUDY_DETAIL") != nullptr)
        std::printf("    %s\n", corrector.describe().c_str());
      for (const bool extrapolate : {false, true}) {
        vrreg::CorrectionQuery query(cell.targets_sensor_m, cell.targets_robot_m, cell.targets_q_rad);
        query.extrapolate = extrapolate;
        const vrreg::TargetCorrection r = corrector.correct(query);
        Sum& sum = extrapolate ? all : ok;
        for (Eigen::Index t = 0; t < cell.targets_robot_m.cols(); ++t) {
          if (!vrreg::is_corrected(r.stencils[static_cast<std::size_t>(t)].status)) {
            ++sum.flagged;
            continue;
          }
          const double tre_m = (r.corrected_robot_m.col(t) - cell.targets_robot_m.col(t)).norm();
          sum.add(tre_m, r.predicted_sd_m(t),
                  (r.uncorrected_robot_m.col(t) - cell.targets_robot_m.col(t)).norm());
        }
      }
    }
    std::printf("  %-28s TRE %.3f mm, TRE/sd %.2f (%d; %d flagged); extrapolate: TRE/sd %.2f (%d)\n",
                c.name, 1e3 * std::sqrt(ok.tre2 / ok.n), ok.rms(), ok.n, ok.flagged, all.rms(),
                all.n);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "rail") {
    rail_study(argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1,
               argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 5);
    return 0;
  }
  const std::uint64_t first = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1;
  const std::uint64_t seeds = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 5;
  const std::vector<Layout> layouts{{3, 0.02, 1}, {4, 0.02, 3}, {6, 0.02, 3},
                                    {6, 0.02, 1}, {4, 0.05, 1}, {5, 0.01, 3}};
  const std::vector<FarPhysics> physics{
      FarPhysics::kTrackerWarp, FarPhysics::kTrackerAxisWarp, FarPhysics::kTrackerScale,
      FarPhysics::kTrackerAxisWarpAndScale, FarPhysics::kUr5Robot, FarPhysics::kLwr4Robot};
  Table table;
  for (const FarPhysics p : physics) {
    const char* only = std::getenv("STUDY_PHYSICS");
    if (only != nullptr && std::string(only).find(to_string(p)) == std::string::npos) continue;
    for (const Layout& layout : layouts) {
      for (std::uint64_t seed = first; seed < first + seeds; ++seed) {
        vrreg::simulation::FarFieldCellOptions o;
        o.physics = p;
        o.nodes = layout.nodes;
        o.spacing_m = layout.spacing_m;
        o.repeats = layout.repeats;
        o.seed = seed;
        run_cell(vrreg::simulation::far_field_cell(o), p, layout, table);
      }
    }
  }
  std::printf("RMS of TRE/sd of extrapolated targets, seeds %llu-%llu (n; flagged)\n",
              static_cast<unsigned long long>(first),
              static_cast<unsigned long long>(first + seeds - 1));
  std::printf("%-10s %-10s %16s %16s %16s\n", "physics", "method", "1x", "10x", "100x");
  std::string last;
  for (const FarPhysics p : physics) {
    for (const char* m : {"grid", "scattered", "octuplet", "trilinear", "kriging", "rbf", "joint"}) {
      std::string line;
      bool any = false;
      for (const double d : {1.0, 10.0, 100.0}) {
        const auto it = table.find({to_string(p), m, d});
        char cell[96];
        if (it == table.end() || it->second.n == 0) {
          std::snprintf(cell, sizeof cell, "%16s", "-");
        } else {
          any = true;
          const Sum& u = it->second;
          if (std::getenv("STUDY_DETAIL") != nullptr) {
            std::snprintf(cell, sizeof cell, "%5.2f %6.3f/%6.3f/%6.3f", u.rms(),
                          1e3 * std::sqrt(u.tre2 / u.n), 1e3 * std::sqrt(u.sd2 / u.n),
                          1e3 * std::sqrt(u.unc2 / u.n));
          } else {
            std::snprintf(cell, sizeof cell, "%8.2f (%3d;%d)", u.rms(), u.n, u.flagged);
          }
        }
        line += " ";
        line += cell;
      }
      if (any) std::printf("%-10s %-10s%s\n", to_string(p), m, line.c_str());
    }
  }
  return 0;
}
