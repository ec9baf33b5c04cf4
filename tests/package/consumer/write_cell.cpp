// SPDX-License-Identifier: Apache-2.0
// The consumer's cell (cell.hpp) as a measurement CSV on stdout, for the command line to compare.
#include <cstdio>

#include "cell.hpp"

int main() {
  std::puts("point,role,robot_x_m,robot_y_m,robot_z_m,sensor_x_m,sensor_y_m,sensor_z_m");
  const vrreg::MeasuredPoints sets[] = {cell_fiducials(), cell_targets()};
  for (int s = 0; s < 2; ++s) {
    for (Eigen::Index i = 0; i < sets[s].size(); ++i) {
      const Eigen::Vector3d y = sets[s].robot_m.col(i), x = sets[s].sensor_m.col(i);
      std::printf("%s,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  sets[s].names[static_cast<std::size_t>(i)].c_str(),
                  s == 0 ? "fiducial" : "target", y.x(), y.y(), y.z(), x.x(), x.y(), x.z());
    }
  }
}
