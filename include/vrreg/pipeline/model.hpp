// SPDX-License-Identifier: Apache-2.0
#pragma once
// The registration model: what `register_fiducials` builds, the model file holds, and `evaluate`
// and `correct` use: the transform, the fiducials it came from, their RRBC corrections (Eq. 6),
// how to interpolate them (Eq. 7) and how arm configurations are treated (Procedure 2).
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/corrector.hpp"
#include "vrreg/correction/interpolation.hpp"
#include "vrreg/correction/orientation_field.hpp"
#include "vrreg/metrics/rigid_body_sampled.hpp"
#include "vrreg/pipeline/marker_offset_model.hpp"
#include "vrreg/planning/procedure2.hpp"

namespace vrreg {

/// One update of a registered model from a few points read later (pipeline/update.hpp): its
/// lineage, so that a model says which model it came from, from which points and when.
struct ModelUpdate {
  std::string change{};               ///< "bump" (the sensor moved) or "drift" (the robot changed)
  std::string parent{};               ///< the model it was made from (file name, or as given)
  std::string points_source{};        ///< the file of the readings it used
  std::vector<std::string> points{};  ///< the points it used ("name" or "name@config")
  std::string time{};                 ///< when, as given (ISO 8601)
  double fit_rms_m = 0.0;             ///< RMS residual of the update's fit [m]
};

/// Everything needed to correct new targets: the registration and the fiducial corrections.
struct RegistrationModel {
  static constexpr int kFormatVersion = 2;
  SimilarityTransform T_robot_sensor{};  ///< Y ~ R X + tau (Eq. 2); scale 1 unless estimated
  std::vector<Location>
      fiducials{};                 ///< nominal robot and averaged sensor positions, labels, joints
  Points3 corrections_sensor_m{};  ///< epsilon_j (Eq. 6), one column per fiducial, sensor frame
  InterpolationSettings interpolation{};  ///< the default of evaluate and correct
  std::optional<int> config{};            ///< configuration label the model was built for, if any
  /// Strategy 2: `fiducials` carry Strategy 2 labels. Strategy 3: `fiducials` hold every arm
  /// configuration, corrected against the one registration from `registration_fiducials`.
  planning::Procedure2 procedure2{};
  double fre_m = 0.0;                ///< FRE of the registration (Eq. 2)
  double sigma_l_m = 0.0;            ///< sigma_L over the registered fiducial pairs (Eq. 1)
  SigmaLSampling sigma_l_sampling{};    ///< sampled: sigma_l_m is estimated from a sample of pairs
  std::optional<double> sigma_rep_m{};  ///< robot repeatability given when building (Eq. 9) [m]
  std::string source{};                 ///< the fiducial file (or "arrays") it came from
  /// Hand-eye registration (register_with_marker_offset): the estimated marker offset; the
  /// fiducials' robot positions and every target's come from forward kinematics with it.
  std::optional<MarkerOffsetModel> marker_offset{};
  /// The arm the fiducials' joints belong to, up to the marker (the joint-space field model).
  std::optional<kinematics::SerialChain> robot{};
  /// The corrector fitted on these fiducials for `interpolation` (and Procedure 2): evaluate and
  /// correct use it without fitting again; empty when none was fitted (the default linear
  /// interpolation could not be used on these fiducials, or the model was built by hand).
  std::optional<Corrector> corrector{};
  /// With rigid-body markers (every fiducial has measured and commanded orientations): the
  /// orientation field fitted with `corrector` (correction/orientation_field.hpp), used by
  /// evaluate and correct whenever they use `corrector` itself.
  std::optional<OrientationCorrector> orientation_corrector{};
  /// Monitor points read when the model was registered, one Location per visit (sensor frame of
  /// the registration): today's readings of them are compared with these (pipeline/check.hpp).
  std::vector<Location> monitors{};
  /// After the sensor moved (a bump, pipeline/update.hpp): today's sensor frame -> the frame the
  /// fiducials were read in, applied to every point before it is corrected; empty: unmoved.
  std::optional<RigidTransform> T_registered_sensor{};
  std::vector<ModelUpdate> lineage{};  ///< the updates since registration, oldest first

  /// What RRBC interpolates (Eq. 6-8): the transform, fiducial positions, corrections, order.
  [[nodiscard]] CorrectionField correction_field() const;
  /// Throws InputError when the parts disagree (counts, non-finite values, no fiducials).
  void validate() const;
  /// `sensor_m` (today's sensor frame) in the frame the fiducials were read in [m].
  [[nodiscard]] Points3 registered_sensor_points(const ConstPoints3Ref& sensor_m) const;
  /// An orientation measured in today's sensor frame, in the frame the fiducials were read in.
  [[nodiscard]] Eigen::Quaterniond registered_sensor_orientation(
      const Eigen::Quaterniond& q_sensor_marker) const;
  /// Whether every fiducial has a measured and a commanded orientation (rigid-body markers):
  /// what an orientation field is fitted on.
  [[nodiscard]] bool has_fiducial_orientations() const;
};

/// The corrector `saved` describes, restored on the model's fiducials without fitting (what io
/// does when it reads a model file). Throws InputError when the state does not fit the model.
Corrector restore_corrector(const RegistrationModel& model, const SavedCorrector& saved);

/// The orientation field `saved` describes, restored on the model's fiducials and its corrector
/// without fitting. Throws InputError when the model has no corrector or fiducial orientations,
/// or the state does not fit them.
OrientationCorrector restore_orientation_corrector(const RegistrationModel& model,
                                                   const SavedOrientationCorrector& saved);

}  // namespace vrreg
