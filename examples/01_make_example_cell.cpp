// SPDX-License-Identifier: Apache-2.0
// Example 1: make a small measurement file for a simulated cell, with the library's own pieces.
//
//   build/release/examples/example_01_make_example_cell [SEED] [OUT.csv]
//
// The robot visits a 9 x 9 x 7 grid at 25 mm (200 x 200 x 150 mm); targets are the nodes with all
// indices odd (4 x 4 x 3 = 48), the rest (519) are fiducials. The robot lands off its nominal
// positions by a smooth + wavy error field (about 1 mm + 0.08 mm RMS); a tracker 2 m away
// reads each position K = 4 times with 0.058 mm noise per axis. This is the file that
// examples/data/example-cell.csv holds (seed 1).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "vrreg/core/random.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/measurement_csv_writer.hpp"
#include "vrreg/simulation/cartesian_error_field.hpp"

int main(int argc, char** argv) {
  try {
    const std::uint64_t seed = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1;
    const std::string out = argc > 2 ? argv[2] : "example-cell.csv";
    vrreg::Random rng(seed);
    const Eigen::Vector3d centre_robot_m(0.45, -0.10, 0.25);
    const vrreg::CartesianErrorField field =
        vrreg::CartesianErrorField::random(rng, centre_robot_m, 0.1, 1.0e-3, 0.08e-3);
    vrreg::RigidTransform T_sensor_robot;  // where the tracker sees the robot base
    T_sensor_robot.rotation =
        Eigen::AngleAxisd(2.4, Eigen::Vector3d(0.2, 0.3, 0.93).normalized()).toRotationMatrix();
    T_sensor_robot.translation_m = Eigen::Vector3d(0.3, 0.2, 2.0);
    const double spacing_m = 0.025;
    const double sigma_opt_m = 0.058e-3;
    const int readings = 4;

    std::vector<vrreg::io::Reading> rows;
    for (int i = 0; i < 9; ++i) {
      for (int j = 0; j < 9; ++j) {
        for (int k = 0; k < 7; ++k) {
          const Eigen::Vector3d nominal =
              centre_robot_m + spacing_m * Eigen::Vector3d(i - 4.0, j - 4.0, k - 3.0);
          const Eigen::Vector3d actual = nominal + field.error_m(nominal);
          const bool target = i % 2 == 1 && j % 2 == 1 && k % 2 == 1;
          for (int r = 0; r < readings; ++r) {
            vrreg::io::Reading row;
            row.point = (target ? "T" : "F") + std::to_string(i) + "-" + std::to_string(j) + "-" +
                        std::to_string(k);
            row.role = target ? vrreg::Role::kTarget : vrreg::Role::kFiducial;
            row.robot_m = nominal;
            row.sensor_m = T_sensor_robot.apply(actual) + rng.normal3(sigma_opt_m);
            row.repeat = r;
            rows.push_back(row);
          }
        }
      }
    }
    vrreg::io::write_measurement_csv(
        out, rows,
        {"vrreg example cell: made by examples/01_make_example_cell.cpp, seed " +
             std::to_string(seed),
         "9 x 9 x 7 grid at 25 mm; targets at odd indices; smooth 1 mm + wavy 0.08 mm RMS "
         "robot error; sensor noise 0.058 mm per axis; 4 readings per location"});
    std::printf("wrote %zu readings to %s (seed %llu)\n", rows.size(), out.c_str(),
                static_cast<unsigned long long>(seed));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "example_01_make_example_cell: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
