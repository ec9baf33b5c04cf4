// SPDX-License-Identifier: Apache-2.0
#include "marker_offset_cli.hpp"

#include <cstdio>

#include "cli_support.hpp"
#include "measurement_input.hpp"
#include "robot_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/result_json.hpp"
#include "vrreg/pipeline/marker_offset.hpp"

namespace vrreg::cli {

void MarkerOffsetFlags::add_to(CLI::App& command) {
  CLI::Option* flag = command.add_flag(
      "--estimate-marker-offset", estimate,
      "estimate the marker's position on the flange together with the registration (hand-eye), "
      "from the fiducials' joints; needs --robot and tilted poses (vrreg plan --offset-tilt-deg)");
  command
      .add_option(
          "--marker-offset-mm", known_mm,
          "X Y Z: the marker's known position in the flange frame, mm: robot positions "
          "from the joints by FK with it (instead of the robot_*_mm columns); needs --robot")
      ->expected(3)
      ->excludes(flag);
  command
      .add_option("--joint-offset-sigma-deg", joint_offset_sigma_deg,
                  "with --estimate-marker-offset: the robot's joint zero-offset uncertainty, deg "
                  "(0.65 for the simulated ur5, 0.3 for lwr4; ~0.01 after a robot calibration); "
                  "adds what the robot's own errors do to the offset to its stated uncertainty")
      ->needs(flag)
      ->check(CLI::Range(0.0, 10.0));
  add_robot_option(command, "--robot", robot,
                   "the robot whose joints the file gives (ur3, ur5, ur10, ur5e, lwr4 or a robot "
                   "file, URDF or JSON/YAML): for --estimate-marker-offset and "
                   "--marker-offset-mm, which replace its tool by the marker's offset, and, with "
                   "its tool as the marker's offset, stored in the model for --interpolation "
                   "joint (and auto)");
  links.add_to(command, "--robot");
  command
      .add_option("--min-orientation-spread", min_orientation_spread,
                  "with --estimate-marker-offset: smallest RMS tilt [rad] for which the offset is "
                  "called observable")
      ->needs(flag)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

void MarkerOffsetFlags::check() const {
  VRREG_THROW_UNLESS(!enabled() || !robot.empty(),
                     (estimate ? "--estimate-marker-offset" : "--marker-offset-mm")
                         << " needs --robot (the robot the joints are for)");
}

void run_register_with_marker_offset(const std::string& fiducials_path,
                                     const MarkerOffsetFlags& flags, const RegisterOptions& options,
                                     const std::string& output, bool json) {
  flags.check();
  const kinematics::SerialChain robot = robot_from_args(flags.robot, {}, flags.links.links());
  MarkerOffsetOptions estimation;
  estimation.min_orientation_spread = flags.min_orientation_spread;
  estimation.joint_offset_sigma_rad = units::deg_to_rad(flags.joint_offset_sigma_deg);
  const bool known = !flags.known_mm.empty();
  if (known) check_finite(flags.known_mm, "--marker-offset-mm");
  const MarkerOffsetRegisterResult result =
      known ? register_with_known_marker_offset(
                  read_measurements(fiducials_path), robot,
                  units::mm_to_m(1.0) *
                      Eigen::Vector3d(flags.known_mm[0], flags.known_mm[1], flags.known_mm[2]),
                  options)
            : register_with_marker_offset(read_measurements(fiducials_path), robot, options,
                                          estimation);
  const MarkerOffsetResult& e = result.estimate;
  if (!result.ok()) throw io::FileError(fiducials_path, 0, e.message);
  const RegisterResult& reg = *result.registered;
  if (!output.empty()) io::write_model_json(output, reg.model);

  if (json) {
    nlohmann::json j = io::marker_offset_register_json(result);
    j["source"] = fiducials_path;
    j["robot"] = robot.name();
    j["offset_given"] = known;
    j["model"] = output.empty() ? nlohmann::json(nullptr) : nlohmann::json(output);
    print_json(j);
    return;
  }
  std::printf("registered %zu fiducials from %s with the marker offset %s (robot %s)\n",
              reg.n_registered, fiducials_path.c_str(), known ? "given" : "estimated",
              robot.name().c_str());
  std::printf("  marker offset p_flange_marker %s mm  (marker in the flange frame)\n",
              format_mm3(e.p_flange_marker_m).c_str());
  if (!known) {
    std::printf("  standard uncertainty          %s mm  (per flange axis)\n",
                format_mm3(result.p_std_total_m, 4).c_str());
    std::printf("    from noise                  %s mm\n", format_mm3(e.p_std_m, 4).c_str());
    const std::string sigma =
        flags.joint_offset_sigma_deg > 0.0
            ? "sigma " + format_fixed(flags.joint_offset_sigma_deg, 3) + " deg"
            : "not given: --joint-offset-sigma-deg";
    std::printf("    from joint zero offsets     %s mm  (%s)\n",
                format_mm3(result.p_std_joint_offsets_m, 4).c_str(), sigma.c_str());
  }
  if (e.has_marker_orientation) {
    const Eigen::Quaterniond& q = e.q_flange_marker;
    std::printf("  marker orientation q_flange_marker  x y z w = % .9f % .9f % .9f % .9f  (marker "
                "axes in the flange frame, from the sensor's orientations)\n",
                q.x(), q.y(), q.z(), q.w());
    std::printf("    standard uncertainty        %.4f %.4f %.4f deg  (per flange axis); "
                "orientation noise %.4f deg\n",
                units::rad_to_deg(e.marker_rotation_std_rad.x()),
                units::rad_to_deg(e.marker_rotation_std_rad.y()),
                units::rad_to_deg(e.marker_rotation_std_rad.z()), units::rad_to_deg(e.sigma_rad));
  }
  const Eigen::Matrix3d& r = reg.model.T_robot_sensor.rotation;
  std::printf("  rotation R (sensor -> robot)  [% .9f % .9f % .9f]\n", r(0, 0), r(0, 1), r(0, 2));
  std::printf("                                [% .9f % .9f % .9f]\n", r(1, 0), r(1, 1), r(1, 2));
  std::printf("                                [% .9f % .9f % .9f]\n", r(2, 0), r(2, 1), r(2, 2));
  std::printf("  translation tau               %s mm\n",
              format_mm3(reg.model.T_robot_sensor.translation_m).c_str());
  if (!known) {
    std::printf("  standard uncertainty of tau   %s mm\n",
                format_mm3(e.translation_std_m, 4).c_str());
    std::printf(
        "  FRE                           %s mm  (fit residual with the offset, all %zu "
        "poses)\n",
        format_mm(e.fre_m).c_str(), static_cast<std::size_t>(e.residuals_m.size()));
    std::printf(
        "  orientation spread            %.3f rad  (RMS tilt about the least-tilted "
        "axis)\n",
        e.orientation_spread);
    std::printf("  condition number              %.1f  (scaled Jacobian; large: poorly posed)\n",
                e.condition_number);
  }
  if (!result.offset_only.empty()) {
    std::printf(
        "  offset only, not in RRBC      %zu tilted poses (other orientation than the "
        "grid)\n",
        result.offset_only.size());
  }
  std::printf("  FRE of the RRBC fiducials     %s mm\n", format_mm(reg.registration.fre_m).c_str());
  std::printf("  sigma_L                       %s mm  (rigid-body condition, FK with the offset)\n",
              format_mm(reg.rigid_body.sigma_l_m).c_str());
  if (reg.noise.rho) {
    std::printf("  rho = sigma_L / sigma_noise   %.2f\n", *reg.noise.rho);
  }
  if (!output.empty()) std::printf("  model written to %s\n", output.c_str());
}

}  // namespace vrreg::cli
