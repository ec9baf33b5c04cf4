# SPDX-License-Identifier: Apache-2.0
# result_format_test prints results with fmt (the header that needs it is opt-in for users).
target_link_libraries(${target} PRIVATE fmt::fmt)
