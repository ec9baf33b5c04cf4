// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/robust_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "seed_cells.hpp"
#include "text_table.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::experiments {
namespace {

constexpr RobustScenario kScenarios[] = {RobustScenario::kClean, RobustScenario::kDisplaced1mm,
                                         RobustScenario::kDisplaced2mm, RobustScenario::kSwapped};

// A stream apart from the simulation's, so the planted error does not change the cell.
constexpr std::uint64_t kPlantStream = 0x5eed0b5e55ed0001ULL;

// Plants the scenario's bad fiducial(s) into `set`; returns their names.
std::vector<std::string> plant(MeasurementSet& set, RobustScenario scenario, Random& rng) {
  const std::vector<std::size_t> fiducials = set.select(Role::kFiducial);
  const auto pick = [&] {
    const auto i = static_cast<std::size_t>(rng.uniform() * static_cast<double>(fiducials.size()));
    return fiducials[std::min(i, fiducials.size() - 1)];
  };
  if (scenario == RobustScenario::kClean) return {};
  if (scenario == RobustScenario::kSwapped) {
    const std::size_t a = pick();
    std::size_t b = pick();
    while (b == a) b = pick();
    std::swap(set.locations[a].sensor_m, set.locations[b].sensor_m);
    std::swap(set.locations[a].sensor_sq_dev_m2, set.locations[b].sensor_sq_dev_m2);
    return {set.locations[a].point, set.locations[b].point};
  }
  const double length_m = scenario == RobustScenario::kDisplaced1mm ? 1e-3 : 2e-3;
  const std::size_t a = pick();
  Eigen::Vector3d direction = rng.normal3(1.0);
  while (direction.norm() < 1e-6) direction = rng.normal3(1.0);
  set.locations[a].sensor_m += length_m * direction.normalized();
  return {set.locations[a].point};
}

RobustStudyCell run_cell(const MeasurementSet& clean, std::uint64_t seed, RobustScenario scenario,
                         const RobustStudyOptions& options) {
  RobustStudyCell cell;
  cell.seed = seed;
  cell.scenario = scenario;
  MeasurementSet set = clean;
  Random rng(seed ^ (kPlantStream + static_cast<std::uint64_t>(scenario)));
  cell.planted = plant(set, scenario, rng);

  RegisterOptions plain;
  plain.sigma_rep_m = options.sigma_rep_m;
  plain.rigid_body_statistics = false;
  RegisterOptions robust = plain;
  robust.robust = options.outliers;
  const RegisterResult p = register_fiducials(set, plain);
  const RegisterResult r = register_fiducials(set, robust);
  cell.plain_cor_rms_t_m = evaluate(p.model, set).summary.cor_rms_t_m;
  cell.robust_cor_rms_t_m = evaluate(r.model, set).summary.cor_rms_t_m;
  cell.sigma_m = r.robust->detection.sigma_m;
  cell.scale_is_noise = r.robust->detection.scale_is_noise;
  cell.sigma_noise_m = r.robust->detection.sigma_noise_m.value_or(0.0);
  cell.threshold_sigmas = r.robust->detection.threshold_sigmas;
  cell.found = true;
  cell.planted_sigmas = std::numeric_limits<double>::infinity();
  for (const std::string& name : cell.planted) {
    const auto it = std::find_if(r.robust->rejected.begin(), r.robust->rejected.end(),
                                 [&](const RejectedFiducial& f) { return f.point == name; });
    if (it == r.robust->rejected.end()) {
      cell.found = false;
    } else {
      cell.planted_sigmas = std::min(cell.planted_sigmas, it->sigmas);
    }
  }
  if (!cell.found || cell.planted.empty()) cell.planted_sigmas = 0.0;
  for (const RejectedFiducial& f : r.robust->rejected) {
    (f.filled ? cell.filled : cell.dropped) += 1;
    if (std::find(cell.planted.begin(), cell.planted.end(), f.point) == cell.planted.end()) {
      ++cell.good_rejected;
    }
  }
  return cell;
}

}  // namespace

void RobustStudyOptions::validate() const {
  VRREG_THROW_UNLESS(seeds >= 1, "robust study: need at least 1 seed, got " << seeds);
  check_seed_run(first_seed, static_cast<std::uint64_t>(seeds), "robust study");
  VRREG_THROW_UNLESS(!sigma_rep_m || (std::isfinite(*sigma_rep_m) && *sigma_rep_m >= 0.0),
                     "robust study: sigma_rep must be finite and >= 0");
  outliers.validate();
}

const char* to_string(RobustScenario scenario) {
  switch (scenario) {
    case RobustScenario::kClean:
      return "clean";
    case RobustScenario::kDisplaced1mm:
      return "1 mm displaced";
    case RobustScenario::kDisplaced2mm:
      return "2 mm displaced";
    case RobustScenario::kSwapped:
      return "2 swapped";
  }
  return "?";
}

RobustStudy robust_study(const RobustStudyOptions& options) {
  options.validate();
  RobustStudy study;
  study.options = options;
  const simulation::Testbed testbed = simulation::ur5_testbed();
  study.cells = detail::seed_cells<RobustStudyCell>(
      options.first_seed, static_cast<std::size_t>(options.seeds),
      std::span<const RobustScenario>(kScenarios),
      [&](std::uint64_t seed) {
        simulation::SimulationOptions sim;
        sim.seed = seed;
        return to_measurement_set(
            simulation::simulate_dataset(testbed, simulation::Dataset::kA1, sim));
      },
      [&](const MeasurementSet& clean, std::uint64_t seed, RobustScenario scenario) {
        return run_cell(clean, seed, scenario, options);
      });
  return study;
}

std::string robust_study_text(const RobustStudy& study) {
  const RobustStudyOptions& o = study.options;
  std::string out = fmt::format(
      "robust check on simulated UR5 A1 cells, seeds {}..{}, false-alarm rate {} per cell, {} "
      "neighbours, sigma_rep {}\n",
      o.first_seed, o.first_seed + static_cast<std::uint64_t>(o.seeds) - 1, o.outliers.false_alarm_rate,
      o.outliers.neighbours,
      o.sigma_rep_m ? fmt::format("{:.3f} mm", *o.sigma_rep_m * 1e3) : std::string("not given"));
  text::TextTable table;
  table.add({"scenario", "cells", "found", "no good rejected", "good rejected (max)",
             "planted (min sigma)", "corRMS_T plain mm", "robust mm", "worst robust/plain"});
  for (const RobustScenario scenario : kScenarios) {
    int n = 0, found = 0, clean = 0, good_max = 0;
    double plain = 0.0, robust = 0.0, worst = 0.0;
    double min_sigmas = std::numeric_limits<double>::infinity();
    for (const RobustStudyCell& c : study.cells) {
      if (c.scenario != scenario) continue;
      ++n;
      found += c.found ? 1 : 0;
      clean += c.good_rejected == 0 ? 1 : 0;
      good_max = std::max(good_max, c.good_rejected);
      plain += c.plain_cor_rms_t_m;
      robust += c.robust_cor_rms_t_m;
      worst = std::max(worst, c.robust_cor_rms_t_m / c.plain_cor_rms_t_m);
      if (!c.planted.empty() && c.found) min_sigmas = std::min(min_sigmas, c.planted_sigmas);
    }
    const auto rate = [n](int k) {
      return fmt::format("{}/{} ({:.1f}%)", k, n, 100.0 * k / std::max(n, 1));
    };
    table.add({to_string(scenario), std::to_string(n),
               scenario == RobustScenario::kClean ? "-" : rate(found), rate(clean),
               std::to_string(good_max),
               std::isfinite(min_sigmas) ? fmt::format("{:.1f}", min_sigmas) : "-",
               text::decimal_text(plain / n * 1e3, 3), text::decimal_text(robust / n * 1e3, 3),
               text::decimal_text(worst, 3)});
  }
  out += table.str();
  double sigma_min = std::numeric_limits<double>::infinity(), sigma_max = 0.0;
  double noise_min = sigma_min, noise_max = 0.0, bound = 0.0;
  int from_noise = 0, filled = 0, dropped = 0;
  for (const RobustStudyCell& c : study.cells) {
    sigma_min = std::min(sigma_min, c.sigma_m);
    sigma_max = std::max(sigma_max, c.sigma_m);
    noise_min = std::min(noise_min, c.sigma_noise_m);
    noise_max = std::max(noise_max, c.sigma_noise_m);
    bound = std::max(bound, c.threshold_sigmas);
    from_noise += c.scale_is_noise ? 1 : 0;
    filled += c.filled;
    dropped += c.dropped;
  }
  out += fmt::format("  bound {:.2f} sigma; sigma_noise {:.4f}..{:.4f} mm; scale sigma {:.4f}..{:.4f} "
                     "mm: sigma_noise in {} of {} cells, the spread of the deviations in the "
                     "rest\n",
                     bound, noise_min * 1e3, noise_max * 1e3, sigma_min * 1e3, sigma_max * 1e3,
                     from_noise, study.cells.size());
  out += fmt::format("  rejected fiducials: {} filled from neighbours (grid kept complete), {} "
                     "dropped\n",
                     filled, dropped);
  return out;
}

}  // namespace vrreg::experiments
