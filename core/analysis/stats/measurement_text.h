// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a power number was measured, in words, for tooltips and `power --json`: "external meter",
// "on-board sensor: INA3221 VDD_IN", "software estimate", or "unknown (the source does not say)".
#include <string>

#include "model/provenance.h"

namespace bs {

std::string measurement_text(const Provenance& provenance);

}  // namespace bs
