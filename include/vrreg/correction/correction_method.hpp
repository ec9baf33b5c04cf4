// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one interface every correction method implements (paper Eq. 7 and the field models beyond
// it): fitted once on a registration's fiducials into an immutable object that predicts the
// correction epsilon(T_X) of any number of points, saves its state, and refits on a subset of the
// fiducials for cross-validation. A method is added by one file in src/correction/ and one line
// in the table of method_registry.cpp.
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/corrector_data.hpp"
#include "vrreg/correction/interpolation.hpp"
#include "vrreg/correction/method_state.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/kinematics/joint_distance.hpp"

namespace vrreg {

/// The fewest fiducials any method corrects from (scattered's tetrahedron): with fewer, every
/// method refuses to fit, and the pipeline leaves every point uncorrected ("too few fiducials").
inline constexpr Eigen::Index kMinCorrectableFiducials = 4;

/// What a method needs of each point besides its sensor reading.
struct MethodNeeds {
  bool nominal_robot = false;  ///< the nominal (commanded) robot position: octuplet, Strategy 3
  bool joints = false;         ///< the commanded joints: joint-space model, Strategy 3
};

/// Where a fitted method is asked, one column (entry) per point. A view: the arrays must outlive it.
struct MethodQuery {
  ConstPoints3Ref registered_robot_m;  ///< R X + tau of each point, robot frame [m]
  ConstPoints3Ref robot_nominal_m;     ///< nominal robot positions [m], or 3 x 0 when not needed
  Eigen::Ref<const Eigen::MatrixXd> joints_rad;  ///< commanded joints [rad], or 0 x 0
  std::span<const std::size_t> sequence{};  ///< where each point was read (file line), or empty
  /// Predict beyond the method's support too (a field model's table samples its edge nodes
  /// there, so that interpolation up to the support's face sees the model, not zeros).
  bool beyond_support = false;
};

/// A method's predictions for n points, sized by the caller; predict() fills a range of them.
struct MethodPredictions {
  Points3 corrections_sensor_m{};  ///< epsilon(T_X) (Eq. 7), sensor frame [m]; 0 where not ok
  /// Per point: status (kOk or why there is no prediction) and, for the paper's stencils, the
  /// fiducials and weights of Eq. 7.
  std::vector<Stencil> stencils{};
  /// The predicted standard uncertainty of a corrected point's 3D error [m], for methods with
  /// their own (kriging); empty otherwise.
  Eigen::VectorXd sd_m{};
  /// For methods that judge gaps of their layout (FittedMethod::judges_gaps): the sd a point's
  /// gap adds to its correction's (in quadrature) [m]; empty otherwise.
  Eigen::VectorXd gap_sd_m{};
};

/// Settings a method is fitted with: the model's interpolation settings and Procedure 2's.
struct MethodSettings {
  double cube_edge_m = 0.0;         ///< octuplet cube edge [m] (0: not set)
  double match_tolerance_m = 1e-6;  ///< how close a fiducial must be to a corner or node [m]
  /// Strategy 3 (paper section 4.4): each octuplet corner in the configuration whose joints are
  /// nearest the target's, by this norm.
  std::optional<kinematics::JointNorm> nearest_configuration{};
};

class FittedMethod;

/// What fitting gives: the fitted method, or why the method does not apply to these fiducials
/// (a value, e.g. "fewer than 12 fiducials"; a failure inside a fit is an exception instead).
struct FitOutcome {
  std::unique_ptr<const FittedMethod> fitted{};
  std::string not_applicable{};  ///< empty when fitted
};

/// A correction method fitted on one registration's fiducials. Immutable: every member function
/// is const and safe to call from many threads at once.
class FittedMethod {
 public:
  virtual ~FittedMethod() = default;
  /// The method (never kLinear or kAuto: those resolve to a method when fitted).
  [[nodiscard]] virtual InterpolationMethod method() const = 0;
  /// What was fitted, e.g. "grid 9 x 9 x 7 nodes, 25 mm" or a kriging model's hyperparameters.
  [[nodiscard]] virtual std::string describe() const = 0;
  [[nodiscard]] virtual MethodNeeds needs() const { return {}; }
  /// True when predict() fills MethodPredictions::sd_m.
  [[nodiscard]] virtual bool has_own_sd() const { return false; }
  /// True when predict() fills MethodPredictions::gap_sd_m: the method's support has gaps inside
  /// its ranges (the joint model: a commanded joint between the fiducials' values of it, far
  /// from every one), answered with a wider sd, or flagged where nothing measures them.
  [[nodiscard]] virtual bool judges_gaps() const { return false; }
  /// Points predicted together by one task: blocks start at multiples of it, so results do not
  /// depend on how a batch is split over threads.
  [[nodiscard]] virtual Eigen::Index block_size() const { return 4096; }
  /// Throws InputError when the query cannot be answered at all (called once before predict).
  virtual void check_query(const MethodQuery& /*query*/) const {}
  /// Fills entries [begin, end) of `out` (sized for the whole query).
  virtual void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
                       MethodPredictions& out) const = 0;
  /// Moves points outside the method's support to its nearest point (registered positions and,
  /// for the joint model, joints), in place, and returns how far each moved [m] (infinity where
  /// the distance has no length, e.g. a joint clamped into its range); nullopt for methods that
  /// never answer outside their layout (the paper's stencils).
  [[nodiscard]] virtual std::optional<Eigen::VectorXd> clamp_to_support(
      Points3& /*registered_robot_m*/, Eigen::MatrixXd& /*joints_rad*/) const {
    return std::nullopt;
  }
  /// The arm's orientation error at commanded joints `joints_rad`, rotation vector of the actual
  /// against the nominal orientation, robot frame [rad], for methods that model the arm (the
  /// joint-space model); nullopt for methods that interpolate residuals.
  /// `joint_angles_only`: the part the joint-angle errors give on the nominal arm.
  [[nodiscard]] virtual std::optional<Eigen::Vector3d> rotation_error_rad(
      const Eigen::Ref<const Eigen::VectorXd>& /*joints_rad*/,
      bool /*joint_angles_only*/ = false) const {
    return std::nullopt;
  }
  /// The arm's fitted joint-angle errors at commanded joints [rad] (the joint-space model's);
  /// nullopt for methods that interpolate residuals.
  [[nodiscard]] virtual std::optional<Eigen::VectorXd> joint_angle_errors_rad(
      const Eigen::Ref<const Eigen::VectorXd>& /*joints_rad*/) const {
    return std::nullopt;
  }
  /// What restore() needs besides the fiducials: fitted parameters, factorisations' inputs.
  [[nodiscard]] virtual MethodState save() const = 0;
  /// The same method on a subset of the fiducials (a cross-validation fold). Methods whose
  /// settings are themselves fitted (kriging's hyperparameters, the joint model's degrees) keep
  /// them, so a fold costs a solve, not a search. Default: fitted afresh.
  [[nodiscard]] virtual FitOutcome refit(const CorrectorData& subset,
                                         const MethodSettings& settings) const;
};

/// A correction method: how to check, fit and restore it.
struct CorrectionMethod {
  InterpolationMethod method = InterpolationMethod::kLinear;
  /// Models the whole field (beyond the paper): compared by `auto`, with a predicted sd.
  bool field_model = false;
  /// Why the method cannot be used on `data` with `settings`, checked before any fitting (too
  /// few fiducials, no joints, not a lattice), or empty.
  std::string (*unavailable)(const CorrectorData& data, const MethodSettings& settings) = nullptr;
  /// Fits the method (called only when `unavailable` gave no reason).
  FitOutcome (*fit)(const CorrectorData& data, const MethodSettings& settings) = nullptr;
  /// The fitted method from its saved state and the same fiducials, without fitting.
  std::unique_ptr<const FittedMethod> (*restore)(const MethodState& state,
                                                 const CorrectorData& data,
                                                 const MethodSettings& settings) = nullptr;
};

/// The method behind `method` (not kLinear or kAuto); throws InputError for those.
const CorrectionMethod& correction_method(InterpolationMethod method);

/// Checks and fits `method` (not kLinear or kAuto) on `data`.
FitOutcome fit_method(InterpolationMethod method, const CorrectorData& data,
                      const MethodSettings& settings);

}  // namespace vrreg
