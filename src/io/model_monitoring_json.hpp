// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to io: a model file's monitor points, its sensor move after a bump and its lineage
// (members "monitors", "T_registered_sensor", "lineage"; absent when the model has none).
#include <nlohmann/json.hpp>

#include "json_fields.hpp"
#include "model_units.hpp"
#include "vrreg/pipeline/model.hpp"

namespace vrreg::io::detail {

/// Adds the three members to `out` (only those the model has).
void add_monitoring_json(const RegistrationModel& model, nlohmann::ordered_json& out);

/// Reads what add_monitoring_json writes into `model`; errors name the file and the key.
void read_monitoring(const nlohmann::json& doc, const JsonFields& f, const LengthUnits& units,
                     RegistrationModel& model);

}  // namespace vrreg::io::detail
