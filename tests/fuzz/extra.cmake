# SPDX-License-Identifier: Apache-2.0
# vrreg_fuzz_tests: the fuzz harnesses (fuzz_*.cpp, not *_test.cpp) replayed over their corpora.
file(GLOB fuzz_harnesses CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/fuzz_*.cpp)
target_sources(${target} PRIVATE ${fuzz_harnesses})
target_link_libraries(${target} PRIVATE vrreg_serve)
