// SPDX-License-Identifier: Apache-2.0
// The radial basis function field model (rbf.hpp) as a correction method: fitted on the
// fiducials' nominal robot positions, asked at registered positions. Its sd is the corrector's
// cross-validation, like the other models without a posterior.
#include "method_support.hpp"
#include "vrreg/correction/rbf.hpp"

namespace vrreg::detail {
namespace {

class RbfMethod final : public FittedMethod {
 public:
  // The model is of the corrections' robot-frame components (R epsilon): per-component
  // smoothing must not depend on where the tracker stands.
  RbfMethod(RbfModel model, SupportBox support, const Eigen::Matrix3d& R_robot_sensor,
            CorrectionValues values)
      : model_(std::move(model)),
        support_(support),
        R_robot_sensor_(R_robot_sensor),
        values_(values) {}

  [[nodiscard]] InterpolationMethod method() const override { return InterpolationMethod::kRbf; }
  [[nodiscard]] std::string describe() const override { return model_.describe(values_); }
  // A local model solves a system per point: blocks of 256 let a long batch report progress.
  [[nodiscard]] Eigen::Index block_size() const override { return 256; }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    out.corrections_sensor_m.middleCols(begin, end - begin) =
        R_robot_sensor_.transpose() *
        model_.predict(query.registered_robot_m.middleCols(begin, end - begin)).mean_m;
    flag_outside_support(support_, query, begin, end, out);
  }

  // In a large cell the refit of cross-validation (98 % of the fiducials) keeps the smoothing
  // chosen on all of them: choosing it again costs an eigendecomposition of 1 500 fiducials,
  // most of the fit's time, for the same choice.
  [[nodiscard]] FitOutcome refit(const CorrectorData& subset,
                                 const MethodSettings& settings) const override;

  [[nodiscard]] std::optional<Eigen::VectorXd> clamp_to_support(
      Points3& registered_robot_m, Eigen::MatrixXd& /*joints_rad*/) const override {
    return support_.clamp(registered_robot_m);
  }

  [[nodiscard]] MethodState save() const override {
    MethodState s("rbf");
    model_.save(s);
    return s;
  }

 private:
  RbfModel model_;
  SupportBox support_;
  Eigen::Matrix3d R_robot_sensor_;
  CorrectionValues values_;  ///< the unit describe() prints the LOO RMS in
};

std::string rbf_unavailable(const CorrectorData& data, const MethodSettings&) {
  if (data.size() < kMinFieldModelFiducials) return "fewer than 12 fiducials";
  std::string why = polynomial_unavailable(data, RbfOptions{}.polynomial_degree, "rbf");
  return why.empty() ? coincidence_unavailable(data, "rbf") : why;
}

// A large cell chooses its smoothing on 1 000 fiducials instead of 1 500: the eigendecomposition
// was 2.9 s of the 8.5 s (CPU) register of 10^5 fiducials, and the 1 000 nearest the centroid
// have the same density, so the same smoothing (docs/benchmarks.md, "Large cells").
constexpr Eigen::Index kLargeCellSmoothingBlock = 1000;

FitOutcome fit_rbf(const CorrectorData& data, const MethodSettings& /*settings*/) {
  const Eigen::Matrix3d& R = data.T_robot_sensor.rotation;
  RbfOptions options;
  if (data.size() > kLargeCellFiducials) options.smoothing_block = kLargeCellSmoothingBlock;
  return fitted<RbfMethod>(
      RbfModel::fit(data.fiducials_robot_m, R * data.corrections_sensor_m, options),
      field_support(data.fiducials_robot_m), R, data.values);
}

FitOutcome RbfMethod::refit(const CorrectorData& subset, const MethodSettings& settings) const {
  if (subset.size() <= kLargeCellFiducials) return fit_rbf(subset, settings);
  RbfOptions options;
  options.smoothing = model_.smoothing();
  const Eigen::Matrix3d& R = subset.T_robot_sensor.rotation;
  return fitted<RbfMethod>(
      RbfModel::fit(subset.fiducials_robot_m, R * subset.corrections_sensor_m, options),
      field_support(subset.fiducials_robot_m), R, subset.values);
}

std::unique_ptr<const FittedMethod> restore_rbf(const MethodState& state, const CorrectorData& data,
                                                const MethodSettings& /*settings*/) {
  const Eigen::Matrix3d& R = data.T_robot_sensor.rotation;
  return std::make_unique<const RbfMethod>(
      RbfModel::restore(data.fiducials_robot_m, R * data.corrections_sensor_m, state),
      field_support(data.fiducials_robot_m), R, data.values);
}

}  // namespace

CorrectionMethod rbf_method() {
  return {InterpolationMethod::kRbf, true, rbf_unavailable, fit_rbf, restore_rbf};
}

}  // namespace vrreg::detail
