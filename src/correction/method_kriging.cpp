// SPDX-License-Identifier: Apache-2.0
// The kriging field model (kriging.hpp) as a correction method: fitted on the fiducials' nominal
// robot positions, asked at registered positions; a corrected target's sd is the posterior sd of
// the field plus its own noise (the nugget), in quadrature.
//
// Where the fiducials allow it (base_cylinder.hpp) the field is kriged in cylindrical
// coordinates about the robot's base axis, its components radial, tangential and vertical:
// there an arm's error is close to stationary and axis-aligned, as an anisotropic stationary
// kernel assumes. On the simulated UR5 cells (seed 1) this takes A1 from 0.127 to 0.106 mm and A2
// from 0.137 to 0.096 mm, with the scan of starts in kriging_fit.cpp (docs/field-models.md).
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "base_cylinder.hpp"
#include "method_support.hpp"
#include "vrreg/correction/kriging.hpp"
#include "vrreg/correction/kriging_design.hpp"

namespace vrreg::detail {
namespace {

/// How the field is presented to the kriging model: its input coordinates and the frame of
/// its components.
struct KrigingFrame {
  std::optional<BaseCylinder> cylinder;
  Eigen::Matrix3d R_robot_sensor = Eigen::Matrix3d::Identity();

  [[nodiscard]] Points3 inputs(const ConstPoints3Ref& robot_m) const {
    return cylinder ? cylinder->coordinates(robot_m) : Points3(robot_m);
  }
  // Components in the robot frame (or along the cylinder's axes), never the sensor's: a field
  // model per component must not depend on where the tracker stands.
  [[nodiscard]] Points3 values(const ConstPoints3Ref& robot_m,
                               const ConstPoints3Ref& corrections_sensor_m) const {
    const Points3 robot_frame = R_robot_sensor * corrections_sensor_m;
    return cylinder ? cylinder->to_local(robot_m, robot_frame) : robot_frame;
  }
  [[nodiscard]] Points3 corrections_sensor(const ConstPoints3Ref& robot_m,
                                           const ConstPoints3Ref& values_m) const {
    return R_robot_sensor.transpose() *
           (cylinder ? cylinder->from_local(robot_m, values_m) : Points3(values_m));
  }
};

KrigingFrame frame_of(const CorrectorData& data) {
  KrigingFrame frame;
  frame.cylinder = BaseCylinder::fit(data.fiducials_robot_m);
  frame.R_robot_sensor = data.T_robot_sensor.rotation;
  return frame;
}

KrigingModel fit_in_frame(const KrigingFrame& frame, const CorrectorData& data,
                          const KrigingOptions& options,
                          const std::array<KrigingHyperparameters, 3>* hyperparameters) {
  const Points3 inputs = frame.inputs(data.fiducials_robot_m);
  const Points3 values = frame.values(data.fiducials_robot_m, data.corrections_sensor_m);
  return hyperparameters != nullptr
             ? KrigingModel::with_hyperparameters(inputs, values, *hyperparameters, options)
             : KrigingModel::fit(inputs, values, options);
}

class KrigingMethod final : public FittedMethod {
 public:
  KrigingMethod(KrigingModel model, KrigingOptions options, KrigingFrame frame,
                SupportBox support, CorrectionValues values)
      : model_(std::move(model)),
        options_(std::move(options)),
        frame_(std::move(frame)),
        support_(support),
        values_(values) {}

  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kKriging;
  }
  [[nodiscard]] std::string describe() const override {
    return model_.describe(values_) +
           (frame_.cylinder ? "; in cylindrical coordinates about the base axis (r, r0 phi, z)"
                            : "; in Cartesian robot coordinates");
  }
  [[nodiscard]] bool has_own_sd() const override { return true; }
  // The exact model predicts queries in blocks of 256 (a J x 256 covariance at a time).
  [[nodiscard]] Eigen::Index block_size() const override { return 256; }

  [[nodiscard]] FitOutcome refit(const CorrectorData& subset,
                                 const MethodSettings&) const override {
    std::array<KrigingHyperparameters, 3> h;
    KrigingOptions options = options_;
    options.latent_sd_scale.emplace();  // the parent's leave-one-out calibration, kept
    for (std::size_t a = 0; a < 3; ++a) {
      h[a] = model_.axes()[a].hyperparameters;
      (*options.latent_sd_scale)[a] = model_.axes()[a].latent_sd_scale;
    }
    return fitted<KrigingMethod>(fit_in_frame(frame_, subset, options, &h), options, frame_,
                                 field_support(subset.fiducials_robot_m), subset.values);
  }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    const Points3 at_m = query.registered_robot_m.middleCols(begin, end - begin);
    const FieldPrediction p = model_.predict(frame_.inputs(at_m));
    out.corrections_sensor_m.middleCols(begin, end - begin) =
        frame_.corrections_sensor(at_m, p.mean_m);
    // The 3D sd is the root of the summed per-component variances, the same in any frame.
    const Eigen::Vector3d nugget_var = model_.nugget_sd_m().cwiseAbs2();
    for (Eigen::Index i = begin; i < end; ++i) {
      out.sd_m(i) = std::sqrt((p.sd_m.col(i - begin).cwiseAbs2() + nugget_var).sum());
    }
    flag_outside_support(support_, query, begin, end, out);
  }

  [[nodiscard]] std::optional<Eigen::VectorXd> clamp_to_support(
      Points3& registered_robot_m, Eigen::MatrixXd& /*joints_rad*/) const override {
    return support_.clamp(registered_robot_m);
  }

  [[nodiscard]] MethodState save() const override {
    MethodState s("kriging");
    model_.save(s);
    return s;
  }

 private:
  KrigingModel model_;
  KrigingOptions options_;
  KrigingFrame frame_;
  SupportBox support_;
  CorrectionValues values_;  ///< the unit describe() prints the signal and nugget in
};

constexpr Eigen::Index kLargeCellFitSubset = 300;

KrigingOptions options_for(const CorrectorData& data) {
  KrigingOptions options;
  // The nugget is at least the fiducials' known noise: a field fitted through the noise would
  // promise more than the measurements hold.
  options.noise_sd_m = data.noise_sd_m;
  // A quadratic trend's 10 terms per axis want ~10 fiducials each; fewer leave it to
  // extrapolate wildly at the layout's edge (27 fiducials of A1: 0.92 mm with degree 2,
  // 0.27 mm with degree 0, octuplet RRBC 0.27 mm).
  options.trend_degree = kriging_trend_degree_for(static_cast<Eigen::Index>(data.size()));
  // A large cell, whose local models use 150 neighbours, fits its hyperparameters on 300
  // fiducials instead of 500: the REML fit is O(n^3) per step and was 4.3 s of the 9.5 s (CPU)
  // register of 10^5 fiducials (docs/benchmarks.md, "Large cells").
  if (data.size() > kLargeCellFiducials) options.fit_subset = kLargeCellFitSubset;
  return options;
}

std::string kriging_unavailable(const CorrectorData& data, const MethodSettings& settings) {
  if (data.size() < kMinFieldModelFiducials) return "fewer than 12 fiducials";
  // The other position-only models refuse any shared position when they are built; kriging
  // takes repeated readings of one configuration (its nugget), not another configuration.
  std::string why = configuration_clash(data, settings.match_tolerance_m);
  if (why.empty()) why = polynomial_unavailable(data, options_for(data).trend_degree, "kriging");
  return why;
}

FitOutcome fit_kriging(const CorrectorData& data, const MethodSettings& /*settings*/) {
  const KrigingOptions options = options_for(data);
  KrigingFrame frame = frame_of(data);
  KrigingModel model = fit_in_frame(frame, data, options, nullptr);
  return fitted<KrigingMethod>(std::move(model), options, std::move(frame),
                               field_support(data.fiducials_robot_m), data.values);
}

std::unique_ptr<const FittedMethod> restore_kriging(const MethodState& state,
                                                    const CorrectorData& data,
                                                    const MethodSettings& /*settings*/) {
  KrigingFrame frame = frame_of(data);
  KrigingModel model =
      KrigingModel::restore(frame.inputs(data.fiducials_robot_m),
                            frame.values(data.fiducials_robot_m, data.corrections_sensor_m), state);
  return std::make_unique<const KrigingMethod>(
      std::move(model), options_for(data), std::move(frame),
      field_support(data.fiducials_robot_m), data.values);
}

}  // namespace

CorrectionMethod kriging_method() {
  return {InterpolationMethod::kKriging, true, kriging_unavailable, fit_kriging, restore_kriging};
}

}  // namespace vrreg::detail
