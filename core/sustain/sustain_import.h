// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a sustained run measured in-process goes home (#52's one way home, for this kind): the GUI's Sustained tab and
// `benchscope-cli sustain --workspace` build the same import batch with the same content-hash recipe, so the same
// run is recognised as the same import whichever front end stored it.
#include <optional>
#include <string>

#include "model/power_trace.h"
#include "model/sustain_run.h"
#include "store/home_batch.h"

namespace bs::sustain {

inline constexpr const char* kSustainFormat = "benchscope-sustain-v1";

// `where`: who measured it, for the import's name ("benchscope-cli sustain", "Sustained tab"; util/home_name.h). The
// content hash is of the record's JSON (sustain_json.h). The power trace recorded beside the run is stored (and
// removed) with it.
HomeBatch sustain_import(const SustainRun& run, const std::optional<PowerTrace>& power, const std::string& where);

}  // namespace bs::sustain
