# SPDX-License-Identifier: Apache-2.0
# Orocos KDL (Debian liborocos-kdl-dev) as the numeric-IK peer of the kinematics benchmarks.
find_package(orocos_kdl REQUIRED)
target_include_directories(vrreg_benchmarks SYSTEM PRIVATE ${orocos_kdl_INCLUDE_DIRS})
target_link_libraries(vrreg_benchmarks PRIVATE ${orocos_kdl_LIBRARIES})
# OpenCV's calibrateRobotWorldHandEye (Debian libopencv-calib3d-dev, no CMake config there) as the
# peer of the marker-offset estimate (hand_eye_bench.cpp); optional: without it vrreg's side runs.
find_path(VRREG_OPENCV_INCLUDE_DIR opencv2/calib3d.hpp PATH_SUFFIXES opencv4)
find_library(VRREG_OPENCV_CALIB3D_LIB opencv_calib3d)
find_library(VRREG_OPENCV_CORE_LIB opencv_core)
if(VRREG_OPENCV_INCLUDE_DIR AND VRREG_OPENCV_CALIB3D_LIB AND VRREG_OPENCV_CORE_LIB)
  target_include_directories(vrreg_benchmarks SYSTEM PRIVATE ${VRREG_OPENCV_INCLUDE_DIR})
  target_link_libraries(vrreg_benchmarks PRIVATE ${VRREG_OPENCV_CALIB3D_LIB} ${VRREG_OPENCV_CORE_LIB})
  target_compile_definitions(vrreg_benchmarks PRIVATE VRREG_HAVE_OPENCV)
else()
  message(STATUS "OpenCV calib3d not found: the hand-eye benchmark runs without its OpenCV peer")
endif()
# The URDF test robots (tests/data/urdf) for the numerical IK benchmarks.
target_compile_definitions(vrreg_benchmarks PRIVATE VRREG_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# The correction service's load generator (docs/serve.md, docs/benchmarks.md): a program, not a
# Google Benchmark, because it drives a service in another process (vrreg serve or its Python peer).
add_executable(vrreg_serve_load ${CMAKE_CURRENT_SOURCE_DIR}/serve_load.cpp)
target_link_libraries(vrreg_serve_load PRIVATE Boost::headers Threads::Threads)
vrreg_set_warnings(vrreg_serve_load)
# How honest an extrapolated correction's sd is (docs/uncertainty.md): a program that prints the
# RMS of TRE/sd table per physics, method and distance.
add_executable(vrreg_extrapolation_study ${CMAKE_CURRENT_SOURCE_DIR}/extrapolation_study.cpp)
target_link_libraries(vrreg_extrapolation_study PRIVATE vrreg::vrreg)
vrreg_set_warnings(vrreg_extrapolation_study)
# What lost motion costs and what its correction gives (docs/joint-space-model.md): a program that
# prints RMS_T over the noise floor and TRE/sd per physics, layout and seed.
add_executable(vrreg_lost_motion_study ${CMAKE_CURRENT_SOURCE_DIR}/lost_motion_study.cpp)
target_link_libraries(vrreg_lost_motion_study PRIVATE vrreg::vrreg)
vrreg_set_warnings(vrreg_lost_motion_study)
