# SPDX-License-Identifier: Apache-2.0
# Warnings as errors on our own targets only (never on third-party headers: those are SYSTEM).
# -Wno-restrict: GCC 12 reports false positives inside std::string at -O3 (GCC bug 105329).
function(vrreg_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor -Werror)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()
