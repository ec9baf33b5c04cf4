# SPDX-License-Identifier: Apache-2.0
# libFuzzer executables, one per harness (VRREG_FUZZ, preset `fuzz`, clang only; scripts/fuzz.sh).
# The whole build carries -fsanitize=fuzzer-no-link (coverage feedback) next to ASan + UBSan.
file(GLOB fuzz_harnesses CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/fuzz_*.cpp)
foreach(source ${fuzz_harnesses})
  get_filename_component(stem ${source} NAME_WE)  # fuzz_measurement_csv
  string(REPLACE "fuzz_" "" harness ${stem})
  set(target vrreg_fuzz_${harness})
  add_executable(${target} ${source})
  target_link_libraries(${target} PRIVATE vrreg_robot_io vrreg_serve)
  target_compile_definitions(${target} PRIVATE VRREG_LIBFUZZER)
  target_compile_options(${target} PRIVATE -fsanitize=fuzzer)
  target_link_options(${target} PRIVATE -fsanitize=fuzzer)
  set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/fuzz)
  vrreg_set_warnings(${target})
  list(APPEND vrreg_fuzzers ${target})
endforeach()
add_custom_target(vrreg_fuzzers DEPENDS ${vrreg_fuzzers})
