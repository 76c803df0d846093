// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A current-only log gets power from a voltage it does not carry (issue #32.2): a supply voltage the user types
// (PowerTrace::supply_voltage_v), or another log's voltage channel recorded at the same time (a bench supply's
// log beside a current clamp's). This file does the second: the other log's voltage interpolated onto this log's
// time axis. It also says, in words, why a log cannot give power, for the views that must leave it out.
#include <optional>
#include <string>

#include "model/power_trace.h"

namespace bs {

// Adds to `target` a voltage channel "<channel> from <source label>" holding `source`'s channel `channel`
// linearly interpolated at each of target's timestamps. The two logs are put on one axis by their absolute start
// times when both have them, else both start at 0 s. Outside the source's span (and next to its missing samples)
// the value is NaN: never extrapolated, never zero. Returns false, leaving target unchanged, when `source` has no
// voltage channel of that name or no samples.
bool borrow_voltage(PowerTrace& target, const PowerTrace& source, const std::string& channel);

// Why `trace` yields no power series: "no current or power channel", "current only: no voltage channel and no
// supply voltage set (set one: right-click the log > Supply voltage…)". nullopt when it gives power.
std::optional<std::string> why_no_power(const PowerTrace& trace);

}  // namespace bs
