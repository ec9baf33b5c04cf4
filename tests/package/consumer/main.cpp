// SPDX-License-Identifier: Apache-2.0
// An outside program on the installed front door: register 27 fiducials and RRBC-correct 8
// targets from in-memory arrays [m] (cell.hpp), print the robot positions to command [mm].
#include <cstdio>
#include <vrreg/vrreg.hpp>

#include "cell.hpp"

int main() {
  const vrreg::RegisterResult r =
      vrreg::register_fiducials(cell_fiducials(), {.sigma_rep_m = 5e-5});
  const vrreg::CorrectResult c = vrreg::correct(r.model, cell_targets(), {.exact = false});
  std::printf("FRE %.6f mm, %s\n", 1e3 * r.registration.fre_m, c.correction.layout.c_str());
  for (std::size_t i = 0; i < c.names.size(); ++i) {
    const Eigen::Vector3d p_mm = 1e3 * c.correction.corrected_robot_m.col(static_cast<Eigen::Index>(i));
    std::printf("%s %.9f %.9f %.9f\n", c.names[i].c_str(), p_mm.x(), p_mm.y(), p_mm.z());
  }
}
