# SPDX-License-Identifier: Apache-2.0
# One switch for ASan + UBSan on everything we build (design.md section 7).
#
# UBSan's null, alignment and object-size checks are left out: they instrument every Eigen
# coefficient access, which made the sanitized build take ~40 % longer to compile and its
# Eigen-heavy tests several times longer to run, and they add little here. ASan already reports a
# null dereference (SEGV with its stack) and every out-of-bounds access that object-size would
# catch; a misaligned load is not a fault on x86-64. The checks that ASan cannot make stay on:
# signed overflow, shifts, bounds of arrays, float-to-int overflow, bool/enum loads, vptr,
# unreachable, missing return, pointer overflow.
if(VRREG_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize=null,alignment,object-size
                      -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()
