// SPDX-License-Identifier: Apache-2.0
#pragma once
// The cross-validation table of the field models (beyond the paper, docs/field-models.md); the
// types live with the correction methods they compare.
#include "vrreg/correction/cross_validation.hpp"
