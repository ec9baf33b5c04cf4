# SPDX-License-Identifier: Apache-2.0
# The contract suite's far-field and rail cells come from the simulated test beds.
target_link_libraries(${target} PRIVATE vrreg_simulation)
