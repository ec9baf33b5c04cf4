// Example 2: register a cell and measure how accurate the registration really is, with RRBC.
//
//   build/release/examples/example_02_register_and_evaluate [CELL.csv] [CUBE_MM]
//
// 1. read a measurement CSV (default examples/data/example-cell.csv, the file of example 1);
// 2. register its fiducials (paper Eq. 2) and compute their RRBC corrections (Eq. 6);
// 3. correct each target from the 8 fiducials at the corners of a cube around it (octuplet,
//    Eq. 7-8; edge CUBE_MM, default 50 mm: the example cell's targets sit at the centres of
//    50 mm cubes of fiducials);
// 4. print RMS_T uncorrected and corrected (Eq. 4), gamma and N_bad (section 5.1).
// The same as `vrreg register` then `vrreg evaluate --interpolation octuplet --cube-mm 50`.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "vrreg/core/model.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/improvement.hpp"
#include "vrreg/metrics/rigid_body.hpp"
#include "vrreg/registration/rigid.hpp"

int main(int argc, char** argv) {
  try {
    const std::string path = argc > 1 ? argv[1] : "examples/data/example-cell.csv";
    const double cube_m = (argc > 2 ? std::strtod(argv[2], nullptr) : 50.0) * 1e-3;

    // 1. Read: repeat readings of a location are averaged; lengths are metres from here on.
    const vrreg::MeasurementSet set = vrreg::io::read_measurement_csv(path);
    const std::vector<std::size_t> fiducials = set.select(vrreg::Role::kFiducial);
    const std::vector<std::size_t> targets = set.select(vrreg::Role::kTarget);
    const vrreg::Points3 fid_sensor = set.sensor_points(fiducials);
    const vrreg::Points3 fid_robot = set.robot_points(fiducials);

    // 2. Register (Eq. 2) and keep what correcting needs: the fiducials and their epsilon_j.
    const vrreg::RegistrationResult reg = vrreg::register_rigid(fid_sensor, fid_robot);
    vrreg::RegistrationModel model;
    model.T_robot_sensor = reg.T_robot_sensor;
    model.fre_m = reg.fre_m;
    for (std::size_t i : fiducials) model.fiducials.push_back(set.locations[i]);
    model.corrections_sensor_m =
        vrreg::fiducial_corrections(reg.T_robot_sensor, fid_sensor, fid_robot);
    model.interpolation.method = vrreg::InterpolationMethod::kOctuplet;
    model.interpolation.cube_edge_m = cube_m;
    const double sigma_l_m = vrreg::rigid_body_statistics(fid_sensor, fid_robot).sigma_l_m;

    // 3. Correct the targets measured by the sensor and map them to the robot frame.
    const vrreg::Points3 tgt_sensor = set.sensor_points(targets);
    const vrreg::Points3 tgt_robot = set.robot_points(targets);
    const vrreg::TargetCorrection c =
        vrreg::correct_targets(model, tgt_sensor, tgt_robot, model.interpolation);

    // 4. TRE against the targets' robot positions (Eq. 3), RMS_T (Eq. 4), gamma, N_bad.
    const Eigen::VectorXd unc = vrreg::point_errors(c.uncorrected_robot_m, tgt_robot);
    const Eigen::VectorXd cor = vrreg::point_errors(c.corrected_robot_m, tgt_robot);
    const vrreg::ImprovementSummary s = vrreg::summarize_improvement(unc, cor);

    std::printf("%s: %zu fiducials, %zu targets\n", path.c_str(), fiducials.size(), targets.size());
    std::printf("  FRE                %.3f mm   sigma_L %.3f mm\n", reg.fre_m * 1e3,
                sigma_l_m * 1e3);
    std::printf("  RMS_T uncorrected  %.3f mm\n", s.unc_rms_t_m * 1e3);
    std::printf("  RMS_T corrected    %.3f mm   (octuplet, %.0f mm cubes; %d not correctable)\n",
                s.cor_rms_t_m * 1e3, cube_m * 1e3, c.n_flagged);
    std::printf("  gamma              %.1f %%\n", 100.0 * s.gamma);
    std::printf("  N_bad              %d of %d targets got worse\n", s.n_bad, s.n_targets);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "example_02: %s\n", e.what());
    return 1;
  }
}
