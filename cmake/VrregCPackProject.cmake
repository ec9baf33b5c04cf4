# SPDX-License-Identifier: Apache-2.0
# Read by cpack (CPACK_PROJECT_CONFIG_FILE): each .deb's Description starts with its own synopsis
# (CPACK_DEBIAN_<COMPONENT>_DESCRIPTION), not with the project's summary.
unset(CPACK_PACKAGE_DESCRIPTION_SUMMARY)
