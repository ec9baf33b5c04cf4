// The radial basis function field model (rbf.hpp) as a correction method: fitted on the
// fiducials' nominal robot positions, asked at registered positions. Its sd is the corrector's
// cross-validation, like the other models without a posterior.
#include "method_support.hpp"
#include "vrreg/correction/rbf.hpp"

namespace vrreg::detail {
namespace {

class RbfMethod final : public FittedMethod {
 public:
  explicit RbfMethod(RbfModel model) : model_(std::move(model)) {}

  [[nodiscard]] InterpolationMethod method() const override { return InterpolationMethod::kRbf; }
  [[nodiscard]] std::string describe() const override { return model_.describe(); }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    out.corrections_sensor_m.middleCols(begin, end - begin) =
        model_.predict(query.registered_robot_m.middleCols(begin, end - begin)).mean_m;
    for (Eigen::Index i = begin; i < end; ++i) out.stencils[static_cast<std::size_t>(i)] = Stencil{};
  }

  [[nodiscard]] MethodState save() const override {
    MethodState s("rbf");
    model_.save(s);
    return s;
  }

 private:
  RbfModel model_;
};

std::string rbf_unavailable(const CorrectorData& data, const MethodSettings&) {
  if (data.size() < kMinFieldModelFiducials) return "fewer than 12 fiducials";
  std::string why = polynomial_unavailable(data, RbfOptions{}.polynomial_degree, "rbf");
  return why.empty() ? coincidence_unavailable(data, "rbf") : why;
}

FitOutcome fit_rbf(const CorrectorData& data, const MethodSettings&) {
  return fitted<RbfMethod>(RbfModel::fit(data.fiducials_robot_m, data.corrections_sensor_m));
}

std::unique_ptr<const FittedMethod> restore_rbf(const MethodState& state, const CorrectorData& data,
                                                const MethodSettings&) {
  return std::make_unique<const RbfMethod>(
      RbfModel::restore(data.fiducials_robot_m, data.corrections_sensor_m, state));
}

}  // namespace

CorrectionMethod rbf_method() {
  return {InterpolationMethod::kRbf, true, rbf_unavailable, fit_rbf, restore_rbf};
}

}  // namespace vrreg::detail
