# SPDX-License-Identifier: Apache-2.0
# Installs the headers and the CMake and pkg-config package files; include after the last
# vrreg_module() (each module installs and exports itself there). docs/install.md shows the use.
include(CMakePackageConfigHelpers)

# The external targets a module may link: the package that defines it (find_dependency arguments),
# its pkg-config module and its Debian -dev package. A module linking anything else fails here,
# so the installed package never misses a dependency.
set(vrreg_external_Eigen3 "Eigen3 3.4 NO_MODULE|eigen3|libeigen3-dev")
set(vrreg_external_TBB "TBB|tbb|libtbb-dev")
set(vrreg_external_nanoflann "nanoflann|nanoflann|libnanoflann-dev")
set(vrreg_external_Qhull "Qhull|qhull_r|libqhull-dev")
set(vrreg_external_yaml-cpp "yaml-cpp|yaml-cpp|libyaml-cpp-dev")
set(vrreg_external_nlohmann_json "nlohmann_json 3.10|nlohmann_json|nlohmann-json3-dev")
set(vrreg_external_fmt "fmt|fmt|libfmt-dev")
set(vrreg_external_urdfdom "urdfdom|urdfdom|liburdfdom-dev")

get_property(modules GLOBAL PROPERTY VRREG_MODULES)
get_property(external_deps GLOBAL PROPERTY VRREG_EXTERNAL_DEPS)
set(packages "")
foreach(dep IN LISTS external_deps)
  string(REGEX REPLACE "::.*" "" package "${dep}")
  if(NOT DEFINED vrreg_external_${package})
    message(FATAL_ERROR "a vrreg module links ${dep}: add its package to cmake/VrregPackage.cmake")
  endif()
  list(APPEND packages ${package})
endforeach()
list(REMOVE_DUPLICATES packages)

set(VRREG_FIND_DEPENDENCIES "")
set(pc_requires "")
set(VRREG_DEB_DEV_DEPENDS "")  # read by cmake/VrregCPack.cmake
foreach(package IN LISTS packages)
  string(REPLACE "|" ";" fields "${vrreg_external_${package}}")
  list(GET fields 0 find_args)
  list(GET fields 1 pc_module)
  list(GET fields 2 deb_package)
  string(APPEND VRREG_FIND_DEPENDENCIES "find_dependency(${find_args})\n")
  list(APPEND pc_requires ${pc_module})
  list(APPEND VRREG_DEB_DEV_DEPENDS ${deb_package})
endforeach()
list(JOIN pc_requires ", " VRREG_PC_REQUIRES)

# Static libraries link in reverse dependency order: the last module declared comes first.
set(VRREG_PC_LIBS "")
foreach(module IN LISTS modules)
  get_target_property(type vrreg_${module} TYPE)
  if(type MATCHES "^(STATIC|SHARED)_LIBRARY$")
    set(VRREG_PC_LIBS "-lvrreg_${module} ${VRREG_PC_LIBS}")
  endif()
endforeach()

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT dev)
install(FILES ${PROJECT_BINARY_DIR}/include/vrreg/config.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vrreg COMPONENT dev)

set(cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/vrreg)
install(EXPORT vrregTargets NAMESPACE vrreg:: DESTINATION ${cmake_dir} COMPONENT dev)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/vrregConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/vrregConfig.cmake INSTALL_DESTINATION ${cmake_dir})
# Before 1.0 a minor release may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/vrregConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vrregConfig.cmake ${PROJECT_BINARY_DIR}/vrregConfigVersion.cmake
        DESTINATION ${cmake_dir} COMPONENT dev)

# The build tree is a package too: find_package(vrreg) with vrreg_DIR=<build>, or
# PKG_CONFIG_PATH=<build>, gives the source and generated headers, the built libraries and the
# Eigen setting (docs/install.md), as the installed package does.
export(EXPORT vrregTargets NAMESPACE vrreg:: FILE ${PROJECT_BINARY_DIR}/vrregTargets.cmake)

# The installed vrreg.pc finds its prefix from its own place (${pcfiledir}), so an installed tree
# can move; it is kept apart from the build tree's, whose paths are absolute.
file(RELATIVE_PATH VRREG_PC_PREFIX_FROM_PCFILEDIR ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig
     ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" VRREG_PC_PREFIX_FROM_PCFILEDIR "${VRREG_PC_PREFIX_FROM_PCFILEDIR}")
string(STRIP "${VRREG_PC_LIBS}" VRREG_PC_LIBS)
set(VRREG_PC_PREFIX "\${pcfiledir}/${VRREG_PC_PREFIX_FROM_PCFILEDIR}")
set(VRREG_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
set(VRREG_PC_INCLUDE_FLAGS "-I\${includedir}")
set(VRREG_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/vrreg.pc.in ${PROJECT_BINARY_DIR}/install/vrreg.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/install/vrreg.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
        COMPONENT dev)
set(VRREG_PC_PREFIX "${PROJECT_BINARY_DIR}")
set(VRREG_PC_INCLUDEDIR "${PROJECT_SOURCE_DIR}/include")
# vrreg/config.hpp is generated into the build's include/.
set(VRREG_PC_INCLUDE_FLAGS "-I\${includedir} -I${PROJECT_BINARY_DIR}/include")
set(VRREG_PC_LIBDIR "$<TARGET_LINKER_FILE_DIR:vrreg_core>")
configure_file(${CMAKE_CURRENT_LIST_DIR}/vrreg.pc.in ${PROJECT_BINARY_DIR}/vrreg.pc.in @ONLY)
get_property(multi_config GLOBAL PROPERTY GENERATOR_IS_MULTI_CONFIG)
if(multi_config)
  file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/$<CONFIG>/vrreg.pc INPUT ${PROJECT_BINARY_DIR}/vrreg.pc.in)
else()
  file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/vrreg.pc INPUT ${PROJECT_BINARY_DIR}/vrreg.pc.in)
endif()
