# SPDX-License-Identifier: Apache-2.0
# The kinematics tests check FK against Orocos KDL (Debian liborocos-kdl-dev), a test-only oracle.
find_package(orocos_kdl REQUIRED)
target_include_directories(${target} SYSTEM PRIVATE ${orocos_kdl_INCLUDE_DIRS})
target_link_libraries(${target} PRIVATE ${orocos_kdl_LIBRARIES})
