// SPDX-License-Identifier: Apache-2.0
#include "field_table.hpp"

#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg::detail {
namespace {

// Catmull-Rom weights of nodes i-1, i, i+1, i+2 at fraction t of cell i.
std::array<double, 4> catmull_rom(double t) {
  const double t2 = t * t;
  const double t3 = t2 * t;
  return {0.5 * (-t3 + 2.0 * t2 - t), 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
          0.5 * (-3.0 * t3 + 4.0 * t2 + t), 0.5 * (t3 - t2)};
}

}  // namespace

FieldTable FieldTable::over(const Eigen::Vector3d& lo_m, const Eigen::Vector3d& hi_m,
                            double spacing_m) {
  VRREG_THROW_UNLESS(std::isfinite(spacing_m) && spacing_m > 0.0 && lo_m.allFinite() &&
                         hi_m.allFinite() && (hi_m.array() >= lo_m.array()).all(),
                     "field table: bad box or spacing " << spacing_m << " m");
  FieldTable t;
  t.support_lo_m = lo_m;
  t.support_hi_m = hi_m;
  t.spacing_m = spacing_m;
  t.origin_m = lo_m.array() - spacing_m;
  for (int a = 0; a < 3; ++a) {
    t.nodes[static_cast<std::size_t>(a)] =
        static_cast<Eigen::Index>(std::ceil((hi_m(a) - lo_m(a)) / spacing_m)) + 4;
  }
  return t;
}

Eigen::Vector3d FieldTable::node_m(Eigen::Index n) const {
  const Eigen::Index i = n % nodes[0];
  const Eigen::Index j = (n / nodes[0]) % nodes[1];
  const Eigen::Index k = n / (nodes[0] * nodes[1]);
  return origin_m + spacing_m * Eigen::Vector3d(static_cast<double>(i), static_cast<double>(j),
                                                static_cast<double>(k));
}

bool FieldTable::lookup(const Eigen::Vector3d& point_m, double tolerance_m,
                        Eigen::Vector3d& correction_m, double& sd_m) const {
  std::array<Eigen::Index, 3> cell{};
  std::array<double, 3> frac{};
  for (int a = 0; a < 3; ++a) {
    const double x = point_m(a);
    if (!(x >= support_lo_m(a) - tolerance_m && x <= support_hi_m(a) + tolerance_m)) return false;
    const double u = (std::clamp(x, support_lo_m(a), support_hi_m(a)) - origin_m(a)) / spacing_m;
    const auto i = std::clamp<Eigen::Index>(static_cast<Eigen::Index>(std::floor(u)), 1,
                                            nodes[static_cast<std::size_t>(a)] - 3);
    cell[static_cast<std::size_t>(a)] = i;
    frac[static_cast<std::size_t>(a)] = u - static_cast<double>(i);
  }
  const std::array<double, 4> wx = catmull_rom(frac[0]);
  const std::array<double, 4> wy = catmull_rom(frac[1]);
  const std::array<double, 4> wz = catmull_rom(frac[2]);
  const Eigen::Index sx = 4;
  const Eigen::Index sy = 4 * nodes[0];
  const Eigen::Index sz = 4 * nodes[0] * nodes[1];
  const double* base = values.data() + (cell[0] - 1) * sx + (cell[1] - 1) * sy + (cell[2] - 1) * sz;
  double c[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j < 4; ++j) {
      const double wyz = wy[static_cast<std::size_t>(j)] * wz[static_cast<std::size_t>(k)];
      const double* row = base + j * sy + k * sz;
      for (int i = 0; i < 4; ++i) {
        const double w = wx[static_cast<std::size_t>(i)] * wyz;
        c[0] += w * row[i * sx];
        c[1] += w * row[i * sx + 1];
        c[2] += w * row[i * sx + 2];
      }
    }
  }
  correction_m = Eigen::Vector3d(c[0], c[1], c[2]);
  sd_m = 0.0;
  if (has_sd) {  // trilinear: never below the smallest corner, never negative
    const double* s = base + sx + sy + sz + 3;
    const double fx = frac[0], fy = frac[1], fz = frac[2];
    const auto at = [&](int i, int j, int k) { return s[i * sx + j * sy + k * sz]; };
    sd_m = (1 - fz) * ((1 - fy) * ((1 - fx) * at(0, 0, 0) + fx * at(1, 0, 0)) +
                       fy * ((1 - fx) * at(0, 1, 0) + fx * at(1, 1, 0))) +
           fz * ((1 - fy) * ((1 - fx) * at(0, 0, 1) + fx * at(1, 0, 1)) +
                 fy * ((1 - fx) * at(0, 1, 1) + fx * at(1, 1, 1)));
    if (rms_correction_deviation_m > 0.0) sd_m = std::hypot(sd_m, rms_correction_deviation_m);
  }
  return true;
}

void FieldTable::save(MethodState& state) const {
  state.put("table.support_lo_m", Eigen::MatrixXd(support_lo_m));
  state.put("table.support_hi_m", Eigen::MatrixXd(support_hi_m));
  state.put("table.spacing_m", spacing_m);
  state.put("table.has_sd", has_sd ? 1.0 : 0.0);
  state.put("table.values_m", values);
  state.put("table.max_correction_deviation_m", max_correction_deviation_m);
  state.put("table.max_sd_relative_deviation", max_sd_relative_deviation);
  state.put("table.rms_correction_deviation_m", rms_correction_deviation_m);
  state.put("table.min_model_sd_m", min_model_sd_m);
  state.put("table.n_checked", static_cast<double>(n_checked));
}

FieldTable FieldTable::restore(const MethodState& state) {
  FieldTable t = over(state.array("table.support_lo_m", 3, 1), state.array("table.support_hi_m", 3, 1),
                      state.number("table.spacing_m"));
  VRREG_THROW_UNLESS(t.size() <= (Eigen::Index{1} << 26),
                     "the saved field table has too many nodes (" << t.size() << ")");
  t.has_sd = state.integer("table.has_sd", 0, 1) == 1;
  t.values = state.array("table.values_m", 4, t.size());
  t.max_correction_deviation_m = state.number("table.max_correction_deviation_m");
  t.max_sd_relative_deviation = state.number("table.max_sd_relative_deviation");
  // Models saved before the table recorded its RMS deviation read it as 0 (their tables were
  // all within 1/4 of the noise of the exact model).
  if (state.has("table.rms_correction_deviation_m")) {
    t.rms_correction_deviation_m = state.number("table.rms_correction_deviation_m");
    t.min_model_sd_m = state.number("table.min_model_sd_m");
  }
  VRREG_THROW_UNLESS(std::isfinite(t.rms_correction_deviation_m) && t.rms_correction_deviation_m >= 0.0,
                     "the saved field table has a bad RMS deviation");
  t.n_checked = static_cast<Eigen::Index>(state.integer("table.n_checked", 0, 1LL << 40));
  return t;
}

}  // namespace vrreg::detail
