# SPDX-License-Identifier: Apache-2.0
# The Debian packages, as Debian splits a library with a command and Python bindings
# (scripts/package.sh; `cpack -G DEB` in a build configured with the `package` preset):
#   vrreg          the command, its manual page and share/vrreg   (install component vrreg)
#   libvrreg-dev   headers, libraries, CMake and pkg-config files  (component dev)
#   python3-vrreg  the Python module, for the interpreter it was built with (component python)
# Each carries /usr/share/doc/<package>/copyright and changelog.gz. Only these components go in, so
# nothing a test, benchmark or example might install.
set(VRREG_DEB_SOURCE_DIR ${PROJECT_SOURCE_DIR}/packaging/debian)
set(vrreg_deb_components vrreg dev)
set(vrreg_deb_package_vrreg vrreg)
set(vrreg_deb_package_dev libvrreg-dev)
set(vrreg_deb_package_python python3-vrreg)
if(TARGET _vrreg)
  list(APPEND vrreg_deb_components python)
endif()

# The changelog's latest entry names the version this build makes (a native package's changelog).
file(STRINGS ${VRREG_DEB_SOURCE_DIR}/changelog changelog_head LIMIT_COUNT 1)
if(NOT changelog_head MATCHES "^vrreg \\(${PROJECT_VERSION}\\) ")
  message(FATAL_ERROR "packaging/debian/changelog starts with '${changelog_head}': add an entry "
                      "for version ${PROJECT_VERSION} (the project's VERSION)")
endif()
set(changelog_gz ${PROJECT_BINARY_DIR}/packaging/changelog.gz)
add_custom_command(OUTPUT ${changelog_gz}
                   COMMAND ${CMAKE_COMMAND} -E copy ${VRREG_DEB_SOURCE_DIR}/changelog
                           ${PROJECT_BINARY_DIR}/packaging/changelog
                   COMMAND gzip -9nf ${PROJECT_BINARY_DIR}/packaging/changelog
                   DEPENDS ${VRREG_DEB_SOURCE_DIR}/changelog VERBATIM)
add_custom_target(vrreg_changelog ALL DEPENDS ${changelog_gz})
foreach(component IN LISTS vrreg_deb_components)
  install(FILES ${VRREG_DEB_SOURCE_DIR}/copyright ${changelog_gz}
          DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/${vrreg_deb_package_${component}}
          COMPONENT ${component})
endforeach()

set(CPACK_PACKAGE_NAME vrreg)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(VRREG_PACKAGE_MAINTAINER "vrreg maintainers <vrreg@example.org>" CACHE STRING
    "Maintainer field of the .deb files")
set(CPACK_PACKAGE_CONTACT "${VRREG_PACKAGE_MAINTAINER}")
set(CPACK_INSTALL_CMAKE_PROJECTS "${PROJECT_BINARY_DIR};${PROJECT_NAME};ALL;/")
set(CPACK_COMPONENTS_ALL ${vrreg_deb_components})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)  # the command and the Python module; static libraries keep their symbols

set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)  # Depends of the binaries: dpkg-shlibdeps
set(CPACK_DEBIAN_VRREG_PACKAGE_NAME vrreg)
set(CPACK_DEBIAN_DEV_PACKAGE_NAME libvrreg-dev)
set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-vrreg)
set(CPACK_DEBIAN_VRREG_PACKAGE_SECTION science)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)

# Descriptions: a synopsis under 80 characters, then lines under 80 (Debian policy 3.4), without
# leading spaces and with an empty line between paragraphs: CPack indents them and writes the " .".
set(vrreg_deb_about
    "vrreg registers a vision system (camera, motion tracker) to a robot arm from\n"
    "fiducials measured in both frames, reports the target registration error on\n"
    "independent targets and corrects it with RRBC, the Restoration of the Rigid\n"
    "Body Condition (NIST).\n")
string(JOIN "" vrreg_deb_about ${vrreg_deb_about})
set(CPACK_DEBIAN_VRREG_DESCRIPTION
    "vision-robot registration that knows its own accuracy\n${vrreg_deb_about}\nThis package contains the vrreg command.")
set(CPACK_DEBIAN_DEV_DESCRIPTION
    "vision-robot registration library - development files\n${vrreg_deb_about}\nThis package contains the C++20 headers, the static libraries and the CMake\n(find_package(vrreg)) and pkg-config files.")
set(CPACK_DEBIAN_PYTHON_DESCRIPTION
    "vision-robot registration - Python 3 module\n${vrreg_deb_about}\nThis package contains the Python 3 module (import vrreg), numpy in and out.")

# libvrreg-dev: the -dev packages whose headers the public headers include or whose libraries the
# static libraries need (VRREG_DEB_DEV_DEPENDS, from cmake/VrregPackage.cmake).
list(JOIN VRREG_DEB_DEV_DEPENDS ", " CPACK_DEBIAN_DEV_PACKAGE_DEPENDS)
# python3-vrreg: the interpreter ABI it was built for and numpy (VRREG_DEB_PYTHON_DEPENDS, from
# python/CMakeLists.txt), with the shared libraries dpkg-shlibdeps finds.
set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "${VRREG_DEB_PYTHON_DEPENDS}")
# CPack would put the project's one-line description in front of each package's own synopsis.
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_CURRENT_LIST_DIR}/VrregCPackProject.cmake)
include(CPack)
