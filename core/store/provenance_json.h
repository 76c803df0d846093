// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>

#include "model/provenance.h"

namespace bs::store {

// Provenance is stored as a JSON text column: it is read whole and never queried field by field.
std::string provenance_to_json(const Provenance& p);
Provenance provenance_from_json(const std::string& text);  // tolerant: unknown or missing keys are ignored

}  // namespace bs::store
