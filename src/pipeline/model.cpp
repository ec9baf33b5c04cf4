// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/model.hpp"

#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {

CorrectionField RegistrationModel::correction_field() const {
  CorrectionField field;
  field.T_robot_sensor = T_robot_sensor;
  field.fiducials_robot_m.resize(3, static_cast<Eigen::Index>(fiducials.size()));
  for (std::size_t j = 0; j < fiducials.size(); ++j) {
    field.fiducials_robot_m.col(static_cast<Eigen::Index>(j)) = fiducials[j].robot_m;
  }
  field.corrections_sensor_m = corrections_sensor_m;
  // The visiting order is known only when every fiducial came from a file line.
  if (std::all_of(fiducials.begin(), fiducials.end(),
                  [](const Location& f) { return f.source_line > 0; })) {
    for (const Location& f : fiducials) field.fiducials_sequence.push_back(f.source_line);
  }
  return field;
}

void RegistrationModel::validate() const {
  VRREG_THROW_UNLESS(!fiducials.empty(), "the model has no fiducials");
  VRREG_THROW_UNLESS(corrections_sensor_m.cols() == static_cast<Eigen::Index>(fiducials.size()),
                     "the model has " << corrections_sensor_m.cols() << " fiducial corrections for "
                                      << fiducials.size() << " fiducials");
  VRREG_THROW_UNLESS(corrections_sensor_m.allFinite(),
                     "the model's fiducial corrections are not all finite");
  const SimilarityTransform& T = T_robot_sensor;
  VRREG_THROW_UNLESS(T.rotation.allFinite() && T.translation_m.allFinite() &&
                         std::isfinite(T.scale) && T.scale > 0.0,
                     "the model's transform is not finite (scale " << T.scale << ")");
  for (const Location& f : fiducials) {
    VRREG_THROW_UNLESS(f.has_robot && f.robot_m.allFinite() && f.sensor_m.allFinite(),
                       "fiducial '" << f.point << "' has no finite position");
  }
  for (const Location& m : monitors) {
    VRREG_THROW_UNLESS(m.sensor_m.allFinite() && m.robot_m.allFinite() && m.n_readings >= 1,
                       "monitor point '" << m.point << "' has no finite reading");
  }
  if (T_registered_sensor) {
    const RigidTransform& M = *T_registered_sensor;
    VRREG_THROW_UNLESS(M.rotation.allFinite() && M.translation_m.allFinite() &&
                           (M.rotation.transpose() * M.rotation - Eigen::Matrix3d::Identity())
                                   .cwiseAbs()
                                   .maxCoeff() < 1e-9 &&
                           M.rotation.determinant() > 0.0,
                       "the model's sensor move (T_registered_sensor) is not a rotation and a "
                       "finite translation");
  }
  for (const std::size_t j : procedure2.registration_fiducials) {
    VRREG_THROW_UNLESS(j < fiducials.size(),
                       "registration fiducial " << j << " of " << fiducials.size());
  }
}

Points3 RegistrationModel::registered_sensor_points(const ConstPoints3Ref& sensor_m) const {
  if (!T_registered_sensor) return sensor_m;
  return T_registered_sensor->apply_all(sensor_m);
}

Eigen::Quaterniond RegistrationModel::registered_sensor_orientation(
    const Eigen::Quaterniond& q_sensor_marker) const {
  if (!T_registered_sensor) return q_sensor_marker;
  return Eigen::Quaterniond(T_registered_sensor->rotation) * q_sensor_marker;
}

bool RegistrationModel::has_fiducial_orientations() const {
  return !fiducials.empty() &&
         std::all_of(fiducials.begin(), fiducials.end(), [](const Location& f) {
           return f.q_sensor_marker.has_value() && f.q_robot_marker.has_value();
         });
}

}  // namespace vrreg
