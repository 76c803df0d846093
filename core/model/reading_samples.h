// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Provenance setting of logs that hold each reading as several samples: "2" for perf stat, whose reading of an
// interval's energy becomes two samples (its start and end) at the interval's mean power. Statistics count
// readings, not samples (analysis/power/power_stats.h, PowerStats::n). Kept in the provenance's settings, which the
// workspace stores already, so no schema change is needed.

namespace bs {

inline constexpr const char* kSamplesPerReadingSetting = "samples per reading";

}  // namespace bs
