// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Provenance <-> JSON, shared by the run JSON writer and the workspace (which stores it as a JSON text column: it
// is read whole and never queried field by field).
#include <string>

#include <nlohmann/json.hpp>

#include "model/provenance.h"

namespace bs {

// All fields as strings; source_file only when asked (it is the importer's note, not part of run JSON v1).
nlohmann::json provenance_to_json(const Provenance& p, bool with_source_file);
// Tolerant: unknown or missing keys are ignored, non-objects give an empty Provenance.
Provenance provenance_from_json(const nlohmann::json& j);

}  // namespace bs
