# SPDX-License-Identifier: Apache-2.0
# vrreg_module(name DEPS ... [PRIVATE_DEPS ...]): library vrreg_<name> from src/<name>/*.cpp, public
# headers in include/vrreg/<name>/. A module without sources yet is an INTERFACE library.
# DEPS are linked PUBLIC; PRIVATE_DEPS only into the module (a static library still passes them
# to its users' link line, as LINK_ONLY). Static by default, shared with BUILD_SHARED_LIBS=ON
# (libvrreg_<name>.so.<major>.<minor>: before 1.0 a minor release may break the ABI). Each module
# joins the umbrella vrreg::vrreg and installs and exports itself as vrreg::<name>
# (cmake/VrregPackage.cmake), so a new module needs no other edit.
include(GNUInstallDirs)

function(vrreg_module name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS" ${ARGN})
  set(target vrreg_${name})
  file(GLOB sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*.cpp)
  if(sources)
    add_library(${target} ${sources})
    set(scope PUBLIC)
    target_link_libraries(${target} PRIVATE ${ARG_PRIVATE_DEPS})
    # PIC so that a shared object (the Python bindings) can link the static libraries.
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON
                          VERSION ${PROJECT_VERSION}
                          SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
    vrreg_set_warnings(${target})
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
    # No link step of its own: its users link what it would have linked privately.
    target_link_libraries(${target} INTERFACE ${ARG_PRIVATE_DEPS})
  endif()
  # include/ of the sources, and of the build for the generated vrreg/config.hpp.
  target_include_directories(${target} ${scope} $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
                                                $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # Eigen's alignment is part of the ABI (results allocated on one side are freed on the other):
  # the library and every user get the same value, whatever -m flags the user compiles with
  # (vrreg/config.hpp checks it; docs/install.md).
  target_compile_definitions(${target} ${scope} EIGEN_MAX_ALIGN_BYTES=${VRREG_EIGEN_MAX_ALIGN_BYTES}
                             EIGEN_MAX_STATIC_ALIGN_BYTES=${VRREG_EIGEN_MAX_STATIC_ALIGN_BYTES})
  target_link_libraries(${target} ${scope} ${ARG_DEPS})
  # The headers are C++20: users of the installed package need it too.
  target_compile_features(${target} ${scope} cxx_std_20)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  add_library(vrreg::${name} ALIAS ${target})

  if(NOT TARGET vrreg)
    add_library(vrreg INTERFACE)
    add_library(vrreg::vrreg ALIAS vrreg)
    install(TARGETS vrreg EXPORT vrregTargets COMPONENT dev)
  endif()
  target_link_libraries(vrreg INTERFACE ${target})

  # Install components: `vrreg` (the command, and shared libraries when built), `dev` (headers,
  # static libraries, CMake and pkg-config files), `python` (the module): one .deb each.
  install(TARGETS ${target} EXPORT vrregTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT vrreg NAMELINK_COMPONENT dev
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT vrreg)
  # Modules in declaration (= dependency) order and the external targets they link, for the
  # package files (find_dependency, pkg-config Libs and Requires, .deb Depends).
  set_property(GLOBAL APPEND PROPERTY VRREG_MODULES ${name})
  foreach(dep IN LISTS ARG_DEPS ARG_PRIVATE_DEPS)
    if(NOT dep MATCHES "^vrreg(_|::)")
      set_property(GLOBAL APPEND PROPERTY VRREG_EXTERNAL_DEPS ${dep})
    endif()
  endforeach()
endfunction()
