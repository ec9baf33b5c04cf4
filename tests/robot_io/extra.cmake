# SPDX-License-Identifier: Apache-2.0
# vrreg export's URDF is read back with urdfdom (Debian liburdfdom-dev), a test-only oracle; its
# YAML with yaml-cpp (robot_io links it).
find_package(urdfdom REQUIRED)
target_include_directories(${target} SYSTEM PRIVATE ${urdfdom_INCLUDE_DIRS})
target_link_libraries(${target} PRIVATE ${urdfdom_LIBRARIES})
# URDF robots are checked against Orocos KDL (Debian liborocos-kdl-dev), a test-only oracle.
find_package(orocos_kdl REQUIRED)
target_include_directories(${target} SYSTEM PRIVATE ${orocos_kdl_INCLUDE_DIRS})
target_link_libraries(${target} PRIVATE ${orocos_kdl_LIBRARIES})
