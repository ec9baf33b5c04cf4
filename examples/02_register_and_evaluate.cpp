// SPDX-License-Identifier: Apache-2.0
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

#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/vrreg.hpp"

int main(int argc, char** argv) {
  try {
    const std::string path = argc > 1 ? argv[1] : "examples/data/example-cell.csv";
    const double cube_m = (argc > 2 ? std::strtod(argv[2], nullptr) : 50.0) * 1e-3;

    // 1. Read: repeat readings of a location are averaged; lengths are metres from here on.
    const vrreg::MeasurementSet set = vrreg::io::read_measurement_csv(path);

    // 2. Register the fiducial rows (Eq. 2) and keep their epsilon_j (Eq. 6) in the model, with
    //    octuplet interpolation as its default.
    vrreg::RegisterOptions options;
    options.interpolation.method = vrreg::InterpolationMethod::kOctuplet;
    options.interpolation.cube_edge_m = cube_m;
    const vrreg::RegisterResult r = vrreg::register_fiducials(set, options);

    // 3-4. Correct the target rows, map them to the robot frame and compare with their robot
    //      positions: TRE (Eq. 3), RMS_T (Eq. 4), gamma, N_bad.
    const vrreg::EvaluateResult e = vrreg::evaluate(r.model, set);
    const vrreg::ImprovementSummary& s = e.summary;

    std::printf("%s: %zu fiducials, %d targets\n", path.c_str(), r.n_registered, s.n_targets);
    std::printf("  FRE                %.3f mm   sigma_L %.3f mm\n", r.registration.fre_m * 1e3,
                r.rigid_body.sigma_l_m * 1e3);
    std::printf("  RMS_T uncorrected  %.3f mm\n", s.unc_rms_t_m * 1e3);
    std::printf("  RMS_T corrected    %.3f mm   (octuplet, %.0f mm cubes; %d not correctable)\n",
                s.cor_rms_t_m * 1e3, cube_m * 1e3, e.correction.n_flagged);
    std::printf("  gamma              %.1f %%\n", 100.0 * s.gamma);
    std::printf("  N_bad              %d of %d targets got worse\n", s.n_bad, s.n_targets);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "example_02: %s\n", e.what());
    return 1;
  }
}
