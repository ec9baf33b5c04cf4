# Orocos KDL (Debian liborocos-kdl-dev) as the numeric-IK peer of the kinematics benchmarks.
find_package(orocos_kdl REQUIRED)
target_include_directories(vrreg_benchmarks SYSTEM PRIVATE ${orocos_kdl_INCLUDE_DIRS})
target_link_libraries(vrreg_benchmarks PRIVATE ${orocos_kdl_LIBRARIES})
