# SPDX-License-Identifier: Apache-2.0
# `cpack -G DEB` in the build directory (scripts/package.sh): one .deb with the command, the static
# libraries, the headers, the CMake and pkg-config files and share/vrreg. Only install rules of
# COMPONENT vrreg go in, so nothing a test, benchmark or example might install.
set(CPACK_PACKAGE_NAME vrreg)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "Registers a vision system to a robot arm from fiducials measured in both frames, reports the\n"
    "target registration error on independent targets and corrects it with RRBC (NIST). Contains\n"
    "the vrreg command, the static C++ libraries, headers, CMake and pkg-config files and the\n"
    "Python module (import vrreg).")
string(JOIN "" CPACK_PACKAGE_DESCRIPTION ${CPACK_PACKAGE_DESCRIPTION})
set(VRREG_PACKAGE_MAINTAINER "vrreg maintainers <vrreg@example.org>" CACHE STRING
    "Maintainer field of the .deb")
set(CPACK_PACKAGE_CONTACT "${VRREG_PACKAGE_MAINTAINER}")
set(CPACK_INSTALL_CMAKE_PROJECTS "${PROJECT_BINARY_DIR};${PROJECT_NAME};vrreg;/")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)

set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The command's shared libraries (dpkg-shlibdeps), plus the -dev packages that the CMake package
# config finds (VRREG_DEB_DEV_DEPENDS, from cmake/VrregPackage.cmake), and what the Python module
# needs when it is built (VRREG_DEB_PYTHON_DEPENDS, from python/CMakeLists.txt).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
list(JOIN VRREG_DEB_DEV_DEPENDS ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
if(VRREG_DEB_PYTHON_DEPENDS)
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", ${VRREG_DEB_PYTHON_DEPENDS}")
endif()
include(CPack)
