# SPDX-License-Identifier: Apache-2.0
# The hardening Debian builds its packages with (dpkg-buildflags' defaults, "hardening=+all" less
# PIE, which Debian's GCC already makes the default): stack protector and clash protection,
# fortified libc calls, control-flow protection on x86, read-only relocations bound at start-up.
# On for every build, so the tests run the code the packages ship; off under the sanitizers (ASan
# replaces the checks) and with VRREG_HARDENING=OFF. None of it changes the arithmetic.
option(VRREG_HARDENING "Build with Debian's hardening flags" ON)
if(VRREG_HARDENING AND NOT VRREG_SANITIZE AND NOT VRREG_FUZZ)
  add_compile_options(-fstack-protector-strong -fstack-clash-protection
                      # _FORTIFY_SOURCE needs the optimiser (a warning, an error with -Werror, at -O0).
                      "$<$<NOT:$<CONFIG:Debug>>:-D_FORTIFY_SOURCE=2>")
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|i.86)$")
    add_compile_options(-fcf-protection)
  endif()
  add_link_options(LINKER:-z,relro LINKER:-z,now)
endif()
