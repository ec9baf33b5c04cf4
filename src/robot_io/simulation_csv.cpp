// SPDX-License-Identifier: Apache-2.0
#include "vrreg/robot_io/simulation_csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/pose.hpp"

namespace vrreg::io {
namespace {

using units::m_to_mm;
using units::rad_to_deg;

std::string g(double value, int precision = 6) { return format_general(value, precision); }

std::string join(const std::vector<double>& values, double scale, int precision) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    out += (i ? ", " : "") + g(values[i] * scale, precision);
  return out + "]";
}

void describe_errors(const simulation::TestbedErrorModel& errors, std::vector<std::string>& out) {
  const simulation::RobotErrorModel& r = errors.robot;
  const simulation::TrackerModel& t = errors.tracker;
  out.push_back("robot errors: joint offset sigma " + g(rad_to_deg(r.joint_offset_sigma_rad)) +
                " deg, link length (a) sigma " + g(m_to_mm(r.link_length_sigma_m)) +
                " mm, link offset (d) sigma " + g(m_to_mm(r.link_offset_sigma_m)) +
                " mm, twist (alpha) sigma " + g(rad_to_deg(r.twist_sigma_rad)) + " deg");
  out.push_back("transmission error A sin(2 pi q / P + phi): A_arcmin " +
                join(r.transmission_amplitude_rad, rad_to_deg(1.0) * 60.0, 6) + ", P_deg " +
                join(r.transmission_period_rad, rad_to_deg(1.0), 6));
  if (!r.lost_motion_rad.empty()) {
    out.push_back("lost motion per joint, arcmin " +
                  join(r.lost_motion_rad, rad_to_deg(1.0) * 60.0, 6) + ", take-up " +
                  g(r.lost_motion_take_up) +
                  ": each joint stops take-up * b / 2 short, against its last move (from home)");
  }
  out.push_back("repeatability sigma " + g(m_to_mm(r.repeatability_sigma_m)) +
                " mm per axis, drawn once per visit; compliance under gravity " +
                (r.compliance
                     ? "on: link_mass_kg " + join(r.link_mass_kg, 1.0, 6) +
                           ", stiffness_nm_per_rad " + join(r.joint_stiffness_nm_per_rad, 1.0, 6) +
                           ", payload_kg " + g(r.payload_kg)
                     : std::string("off")));
  out.push_back("tracker: " + g(t.distance_m) + " m from the volume centre, azimuth " +
                g(rad_to_deg(t.azimuth_rad)) + " deg, elevation " + g(rad_to_deg(t.elevation_rad)) +
                " deg; noise sigma per reading per sensor axis (x, y, z) [" +
                g(m_to_mm(t.noise_sigma_m.x())) + ", " + g(m_to_mm(t.noise_sigma_m.y())) + ", " +
                g(m_to_mm(t.noise_sigma_m.z())) +
                "] mm; K = " + std::to_string(t.readings_per_location) + " readings per visit");
  if (t.rigid_body_radius_m > 0.0) {
    const Eigen::Vector3d sigma_rad = simulation::orientation_noise_sigma_rad(t);
    out.push_back("rigid body: " + std::to_string(t.rigid_body_markers) + " spheres on a " +
                  g(m_to_mm(t.rigid_body_radius_m)) + " mm radius; orientation noise sigma per " +
                  "reading (body x, y, z) [" + g(1e3 * sigma_rad.x()) + ", " +
                  g(1e3 * sigma_rad.y()) + ", " + g(1e3 * sigma_rad.z()) + "] mrad");
  }
}

void describe_robot(const simulation::SimulatedDataset& data, std::vector<std::string>& out) {
  out.push_back("drawn robot (actual - nominal DH, transmission phase):");
  for (std::size_t i = 0; i < data.robot.dh_delta.size(); ++i) {
    const kinematics::DhRow& d = data.robot.dh_delta[i];
    const auto signed_fixed = [](double v, int decimals) {
      return (std::signbit(v) ? "" : "+") + format_fixed(v, decimals);  // printf's %+f
    };
    std::string text = "  joint " + std::to_string(i + 1) + ": dtheta " +
                       signed_fixed(rad_to_deg(d.theta_offset_rad), 5) + " deg, da " +
                       signed_fixed(m_to_mm(d.a_m), 4) + " mm, dd " +
                       signed_fixed(m_to_mm(d.d_m), 4) + " mm, dalpha " +
                       signed_fixed(rad_to_deg(d.alpha_rad), 5) + " deg";
    if (i < data.robot.transmission_phase_rad.size()) {
      text += ", phase " + g(rad_to_deg(data.robot.transmission_phase_rad[i]), 5) + " deg";
    }
    out.push_back(text);
  }
}

}  // namespace

std::vector<Reading> simulated_readings(const simulation::SimulatedDataset& data) {
  const bool with_config = data.has_config;
  const bool with_visit =
      std::any_of(data.visits.begin(), data.visits.end(),
                  [](const simulation::SimulatedVisit& v) { return v.round >= 0; });
  // Via points (one approach direction per joint) are moves the rows do not show: then every row
  // names the joints it came from (its via point, else the previous visit's), so that the reader
  // takes the directions from them rather than from the rows' order.
  const bool with_from =
      std::any_of(data.visits.begin(), data.visits.end(),
                  [](const simulation::SimulatedVisit& v) { return v.via_q_rad.has_value(); });
  std::vector<Reading> rows;
  rows.reserve(data.readings.size());
  for (const simulation::SimulatedReading& r : data.readings) {
    const simulation::SimulatedVisit& visit = data.visits[static_cast<std::size_t>(r.visit)];
    const simulation::PlannedLocation& location =
        data.locations[static_cast<std::size_t>(visit.location)];
    Reading row;
    row.point = location.point;
    row.role = location.role;
    row.robot_m = location.robot_m;
    row.sensor_m = r.sensor_m;
    if (with_config) row.config = visit.config;
    row.q_rad.assign(visit.q_rad.data(), visit.q_rad.data() + visit.q_rad.size());
    if (with_from) {
      const auto v = static_cast<std::size_t>(r.visit);
      const kinematics::JointVector& from =
          visit.via_q_rad ? *visit.via_q_rad : data.visits[v > 0 ? v - 1 : 0].q_rad;
      row.from_q_rad.assign(from.data(), from.data() + from.size());
    }
    row.repeat = r.repeat;
    if (with_visit) row.visit = std::max(visit.round, 0);
    if (r.q_sensor_marker) {
      row.q_sensor_marker = r.q_sensor_marker;
      row.q_robot_marker = Eigen::Quaterniond(visit.R_commanded).normalized();
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<std::string> simulated_dataset_comments(const simulation::SimulatedDataset& data) {
  std::vector<std::string> out;
  const bool lwr = data.dataset == simulation::Dataset::kGrid;
  out.push_back("vrreg simulate: test bed " + data.testbed + ", dataset " +
                simulation::to_string(data.dataset) + ", seed " + std::to_string(data.seed));
  std::size_t targets = 0, monitors = 0;
  for (const auto& l : data.locations) {
    targets += l.role == Role::kTarget ? 1 : 0;
    monitors += l.role == Role::kMonitor ? 1 : 0;
  }
  out.push_back(std::to_string(data.locations.size()) + " nominal locations (" +
                std::to_string(data.locations.size() - targets - monitors) + " fiducials, " +
                std::to_string(targets) + " targets" +
                (monitors > 0 ? ", " + std::to_string(monitors) + " monitor points" : "") + "), " +
                std::to_string(data.visits.size()) + " visits, " +
                std::to_string(data.readings.size()) + " readings; rows in visiting order");
  if (data.time_s != 0.0) {
    const bool bumped = data.time_s >= data.events.bump_time_s && data.events.bump_rms_m > 0.0;
    out.push_back("read " + g(data.time_s / 3600.0, 6) + " h after time 0: links grown by " +
                  g(data.events.thermal.growth_at(data.time_s), 6) + ", tracker " +
                  (bumped ? "bumped " + g(1e3 * data.events.bump_rms_m, 6) + " mm RMS"
                          : std::string("as at time 0")));
  }
  if (data.dataset == simulation::Dataset::kPlan) {
    out.push_back("a plan measured as written: commanded joints and config from the plan");
  } else if (lwr) {
    out.push_back(
        "config = position (1..4) in the analytic IK's list, which ranks the four "
        "configurations by joint distance to the home posture (Strategy 1 order)");
  } else {
    out.push_back("UR controller: one IK solution per location, nearest the previous joints");
  }
  if (data.dataset == simulation::Dataset::kB) {
    out.push_back(
        "B labels: target = A1 grid label, fiducial = target label + _a<cube edge mm>_c<corner>"
        " (corner bits 1 = +x, 2 = +y, 4 = +z); 50 mm cube corners of neighbouring "
        "targets share nominal positions, each visited once per target");
  }
  describe_errors(data.errors, out);
  describe_robot(data, out);
  const Eigen::Vector3d rpy = kinematics::rpy_from_rotation(data.T_robot_sensor.rotation);
  out.push_back("true tracker pose T_robot_sensor: translation [" +
                g(m_to_mm(data.T_robot_sensor.translation_m.x()), 8) + ", " +
                g(m_to_mm(data.T_robot_sensor.translation_m.y()), 8) + ", " +
                g(m_to_mm(data.T_robot_sensor.translation_m.z()), 8) + "] mm, rpy [" +
                g(rad_to_deg(rpy.x()), 8) + ", " + g(rad_to_deg(rpy.y()), 8) + ", " +
                g(rad_to_deg(rpy.z()), 8) + "] deg");
  if (data.marker_flange_m) {
    out.push_back("true marker position in the flange frame p_flange_marker: [" +
                  g(m_to_mm(data.marker_flange_m->x()), 8) + ", " +
                  g(m_to_mm(data.marker_flange_m->y()), 8) + ", " +
                  g(m_to_mm(data.marker_flange_m->z()), 8) +
                  "] mm; robot_*_mm hold the controller's TCP, not the marker");
  }
  out.push_back("robot repeatability spec (for sigma_noise, Eq. 9): " +
                g(m_to_mm(data.sigma_rep_spec_m)) + " mm");
  return out;
}

void write_simulated_dataset_csv(const std::string& path,
                                 const simulation::SimulatedDataset& data) {
  write_measurement_csv(path, simulated_readings(data), simulated_dataset_comments(data));
}

}  // namespace vrreg::io
