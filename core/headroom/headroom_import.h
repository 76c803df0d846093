// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a headroom measurement made in-process goes home (#52's one way home, for this kind): the GUI's Headroom tab
// and `benchscope-cli headroom --workspace` build the same import batch with the same content-hash recipe, so the
// same measurement is recognised as the same import whichever front end stored it. (They hashed different JSON
// before: the tab the record, the CLI the record with its derived summary.)
#include <optional>
#include <string>

#include "headroom/headroom_measurement.h"
#include "model/power_trace.h"
#include "store/home_batch.h"

namespace bs::headroom {

inline constexpr const char* kHeadroomFormat = "benchscope-headroom-v1";

// `where`: who measured it, for the import's name ("benchscope-cli headroom", "Headroom tab"; util/home_name.h). The
// content hash is of the measurement's record (headroom_json.h, without the derived summary). The power trace
// recorded beside the run is stored (and removed) with it.
HomeBatch headroom_import(const HeadroomMeasurement& m, const std::optional<PowerTrace>& power,
                          const std::string& where);

}  // namespace bs::headroom
