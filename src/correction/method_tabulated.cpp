// SPDX-License-Identifier: Apache-2.0
#include "method_tabulated.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>

#include "method_support.hpp"
#include "point_index.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::detail {
namespace {

// The table's spacing: 2/5 of the layout's spacing (the cube root of the box's volume per
// fiducial, or the median nearest-neighbour distance if larger). On the simulated cells (25 mm
// fiducials, kriging length scales from 44 mm) 10 mm nodes keep the table within 1.4 um.
constexpr double kSpacingFraction = 0.4;
// Refine once (half the spacing) when the table strays from the exact model by more than 1/20 of
// a fiducial's measured noise (3D), or 1 um when the noise is unknown: far below what the model
// itself can know, while a finer table costs 8 times the nodes. On the example cell (0.029 mm
// per axis) the 10 mm table of kriging is within 1.4 um.
constexpr double kDeviationPerNoise = 0.05;
constexpr double kDefaultDeviationM = 1e-6;
// How far beyond the target a table may deviate and still be used (5 x 1/20 of the noise).
constexpr double kAcceptFactor = 5.0;
// The largest table deviation accepted against the model's smallest sd: sqrt(1 + 1/9) = 1.054.
constexpr double kSdFraction = 1.0 / 3.0;
// ... and the largest relative deviation of its sd from the model's (trilinear between nodes).
constexpr double kSdRelativeDeviation = 0.25;
constexpr Eigen::Index kMaxNodes = Eigen::Index{1} << 21;
constexpr Eigen::Index kCheckPoints = 2000;
constexpr Eigen::Index kBlock = 256;
constexpr const char* kForm = "form";

void fill(FieldTable& t, const ExactField& exact) {
  const Eigen::Index n = t.size();
  t.values.resize(4, n);
  const Eigen::Index blocks = (n + kBlock - 1) / kBlock;
  std::atomic<bool> sd{false};
  tbb::parallel_for(Eigen::Index{0}, blocks, [&](Eigen::Index b) {
    const Eigen::Index begin = b * kBlock;
    const Eigen::Index count = std::min(kBlock, n - begin);
    Points3 at(3, count);
    for (Eigen::Index i = 0; i < count; ++i) at.col(i) = t.node_m(begin + i);
    Points3 c;
    Eigen::VectorXd s;
    exact(at, c, s);
    t.values.block(0, begin, 3, count) = c;
    if (s.size() == count) {
      t.values.block(3, begin, 1, count) = s.transpose();
      sd = true;
    } else {
      t.values.block(3, begin, 1, count).setZero();
    }
  });
  t.has_sd = sd;
}

// The largest deviations from the exact model at seeded points of the support box.
void check(FieldTable& t, const ExactField& exact) {
  Random rng(1);
  Points3 at(3, kCheckPoints);
  for (Eigen::Index i = 0; i < kCheckPoints; ++i) {
    for (int a = 0; a < 3; ++a) at(a, i) = rng.uniform(t.support_lo_m(a), t.support_hi_m(a));
  }
  Points3 c;
  Eigen::VectorXd s;
  exact(at, c, s);
  t.max_correction_deviation_m = 0.0;
  t.max_sd_relative_deviation = 0.0;
  t.rms_correction_deviation_m = 0.0;  // the lookups below compare the table's own sd
  t.min_model_sd_m = t.has_sd ? std::numeric_limits<double>::infinity() : 0.0;
  double sum_squares = 0.0;
  for (Eigen::Index i = 0; i < kCheckPoints; ++i) {
    Eigen::Vector3d tc;
    double ts = 0.0;
    (void)t.lookup(at.col(i), 0.0, tc, ts);
    const double deviation = (tc - c.col(i)).norm();
    t.max_correction_deviation_m = std::max(t.max_correction_deviation_m, deviation);
    sum_squares += deviation * deviation;
    if (t.has_sd) t.min_model_sd_m = std::min(t.min_model_sd_m, s(i));
    if (t.has_sd && s(i) > 0.0) {
      t.max_sd_relative_deviation = std::max(t.max_sd_relative_deviation, std::abs(ts - s(i)) / s(i));
    }
  }
  t.rms_correction_deviation_m = std::sqrt(sum_squares / static_cast<double>(kCheckPoints));
  t.n_checked = kCheckPoints;
}

class TabulatedMethod final : public FittedMethod {
 public:
  TabulatedMethod(FieldTable table, InterpolationMethod method, MethodState exact_state,
                  std::string exact_description, CorrectionValues values)
      : table_(std::move(table)),
        method_(method),
        exact_state_(std::move(exact_state)),
        exact_description_(std::move(exact_description)),
        values_(values) {}

  [[nodiscard]] InterpolationMethod method() const override { return method_; }
  [[nodiscard]] bool has_own_sd() const override { return table_.has_sd; }
  [[nodiscard]] std::string describe() const override {
    std::ostringstream out;
    out << exact_description_ << "; tabulated every " << units::m_to_mm(table_.spacing_m)
        << " mm (" << table_.nodes[0] << " x " << table_.nodes[1] << " x " << table_.nodes[2]
        << " nodes), within " << table_.max_correction_deviation_m * 1e6 << " "
        << micro_unit(values_) << " of the model (RMS "
        << table_.rms_correction_deviation_m * 1e6 << " " << micro_unit(values_);
    if (table_.has_sd) out << ", in the sd";
    out << ")";
    if (table_.has_sd) out << " and its sd within " << table_.max_sd_relative_deviation * 100 << " %";
    out << " (" << table_.n_checked << " points checked)";
    return out.str();
  }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    for (Eigen::Index i = begin; i < end; ++i) {
      Eigen::Vector3d c;
      double sd = 0.0;
      Stencil& s = out.stencils[static_cast<std::size_t>(i)];
      if (table_.lookup(query.registered_robot_m.col(i), 0.0, c, sd)) {
        s = Stencil{};
        out.corrections_sensor_m.col(i) = c;
      } else {
        s = flagged_stencil(StencilStatus::kOutsideSupport);
        out.corrections_sensor_m.col(i).setZero();
      }
      if (table_.has_sd) out.sd_m(i) = sd;
    }
  }

  [[nodiscard]] std::optional<Eigen::VectorXd> clamp_to_support(
      Points3& registered_robot_m, Eigen::MatrixXd& /*joints_rad*/) const override {
    return SupportBox::clamp_to_box(registered_robot_m, table_.support_lo_m, table_.support_hi_m);
  }

  [[nodiscard]] MethodState save() const override {
    MethodState s = exact_state_;
    s.put_text(kForm, "tabulated");
    s.put_text("exact_description", exact_description_);
    table_.save(s);
    return s;
  }

  // A fold of cross-validation refits the exact model: its table would only blur it.
  [[nodiscard]] FitOutcome refit(const CorrectorData& subset,
                                 const MethodSettings& settings) const override {
    return fit_method(method_, subset, settings);
  }

 private:
  FieldTable table_;
  InterpolationMethod method_;
  MethodState exact_state_;
  std::string exact_description_;
  CorrectionValues values_;  ///< the unit describe() prints the table's deviations in
};

}  // namespace

std::optional<FieldTable> build_field_table(const ExactField& exact, const ConstPoints3Ref& fiducials_robot_m,
                             std::optional<double> noise_sd_m) {
  const double target_m =
      noise_sd_m && *noise_sd_m > 0.0 ? kDeviationPerNoise * std::sqrt(3.0) * *noise_sd_m
                                      : kDefaultDeviationM;
  // The table covers the model's support, margin included, so that it answers where the exact
  // model does.
  const SupportBox support = field_support(fiducials_robot_m);
  const Eigen::Vector3d lo = support.lo_m.array() - support.margin_m;
  const Eigen::Vector3d hi = support.hi_m.array() + support.margin_m;
  double spacing_m = kSpacingFraction * layout_spacing_m(fiducials_robot_m);
  FieldTable t = FieldTable::over(lo, hi, spacing_m);
  while (t.size() > kMaxNodes) {
    spacing_m *= std::cbrt(static_cast<double>(t.size()) / static_cast<double>(kMaxNodes)) * 1.01;
    t = FieldTable::over(lo, hi, spacing_m);
  }
  fill(t, exact);
  check(t, exact);
  FieldTable finer = FieldTable::over(lo, hi, 0.5 * spacing_m);
  if (t.max_correction_deviation_m > target_m && finer.size() <= kMaxNodes) {
    fill(finer, exact);
    check(finer, exact);
    t = std::move(finer);
  }
  // A table within a quarter of the noise answers as the exact model does. A rougher one (length
  // scales below the fiducials' spacing, e.g. a harmonic drive's period seen through an aliasing
  // layout) is still used when the model states an sd, the table's largest deviation stays
  // below a third of the smallest sd and its sd within 25 % of the model's: its RMS deviation then enters every sd in quadrature, so a
  // stated sd grows by at most 5 % while a correction costs microseconds instead of the exact
  // posterior's milliseconds. Otherwise the exact form is kept.
  const bool within_noise = t.max_correction_deviation_m <= kAcceptFactor * target_m;
  const bool within_sd = t.has_sd &&
                         t.max_correction_deviation_m <= kSdFraction * t.min_model_sd_m &&
                         t.max_sd_relative_deviation <= kSdRelativeDeviation;
  if (!within_noise && !within_sd) return std::nullopt;
  return t;
}

std::unique_ptr<const FittedMethod> tabulated_method(FieldTable table, InterpolationMethod method,
                                                     MethodState exact_state,
                                                     std::string exact_description,
                                                     CorrectionValues values) {
  return std::make_unique<const TabulatedMethod>(std::move(table), method, std::move(exact_state),
                                                 std::move(exact_description), values);
}

bool is_tabulated(const MethodState& state) {
  return state.has(kForm) && state.text(kForm) == "tabulated";
}

MethodState exact_state_of(const MethodState& state) {
  MethodState out(state.method());
  const auto table_key = [](const std::string& key) {
    return key == kForm || key == "exact_description" || key.rfind("table.", 0) == 0;
  };
  for (const auto& [key, value] : state.arrays()) {
    if (!table_key(key)) out.put(key, value);
  }
  for (const auto& [key, text] : state.texts()) {
    if (!table_key(key)) out.put_text(key, text);
  }
  return out;
}

std::unique_ptr<const FittedMethod> restore_tabulated(const MethodState& state,
                                                      InterpolationMethod method,
                                                      CorrectionValues values) {
  return tabulated_method(FieldTable::restore(state), method, exact_state_of(state),
                          state.text("exact_description"), values);
}

}  // namespace vrreg::detail
