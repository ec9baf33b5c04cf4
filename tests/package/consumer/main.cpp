// Uses the installed vrreg: recovers a known rigid transform from 27 grid points.
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>
#include <vrreg/registration/rigid.hpp>

int main() {
  vrreg::Points3 sensor(3, 27);
  for (int i = 0; i < 27; ++i) sensor.col(i) << 0.1 * (i % 3), 0.1 * (i / 3 % 3), 0.1 * (i / 9);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const Eigen::Vector3d translation_m(0.5, -0.25, 1.0);
  const vrreg::Points3 robot = (rotation * sensor).colwise() + translation_m;

  const vrreg::RegistrationResult result = vrreg::register_rigid(sensor, robot);
  const Eigen::Vector3d& t = result.T_robot_sensor.translation_m;
  std::printf("translation_m %.6f %.6f %.6f FRE_m %.3g\n", t.x(), t.y(), t.z(), result.fre_m);
  const bool ok = (t - translation_m).norm() < 1e-9 &&
                  (result.T_robot_sensor.rotation - rotation).norm() < 1e-9 && result.fre_m < 1e-9;
  std::puts(ok ? "consumer: ok" : "consumer: WRONG");
  return ok ? 0 : 1;
}
