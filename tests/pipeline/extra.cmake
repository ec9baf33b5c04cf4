# SPDX-License-Identifier: Apache-2.0
# The front door's array path is checked against its file path on the same cells (io reads them).
target_link_libraries(${target} PRIVATE vrreg_io)
