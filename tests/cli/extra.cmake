# SPDX-License-Identifier: Apache-2.0
# file_option_roles_test builds every command's options in process.
target_link_libraries(${target} PRIVATE vrreg_cli_commands)
