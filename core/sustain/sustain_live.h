// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sustained run put together interval by interval from the lines `sustain --json` streams (a robot's run, seen at
// the desk while it goes on): each "interval" line (sustain_json.h's interval_json) adds one interval, and a clock or
// sensor first seen later gets NaN for the intervals before it. What the robot streams is untrusted input: every
// value is checked, and the number of intervals and series is bounded.
#include <nlohmann/json_fwd.hpp>

#include "model/sustain_run.h"

namespace bs::sustain {

// Throws SustainJsonError (sustain_json.h) naming the field and the reason; `so_far` is unchanged then.
void append_interval(SustainRun& so_far, const nlohmann::json& interval);

}  // namespace bs::sustain
