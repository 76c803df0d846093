// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the headroom importers share when they turn a file into a HeadroomMeasurement: one phase ("as recorded": the
// file does not say what ran beside the loop), a thread known only by its summary (min / mean / max and perhaps n,
// no histogram), and the batch around the measurement.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "headroom/headroom_measurement.h"
#include "store/import_batch.h"

namespace bs::headroom_import {

// The name of the single phase of an imported measurement: what ran beside the loop is not in the file.
inline constexpr std::string_view kImportedPhase = "as recorded";

// Said in the phase notes of every thread that has no distribution.
inline constexpr std::string_view kSummaryOnlyNote =
    "summary only: the file keeps no histogram, so percentiles and deadline misses are not in the file";

// A thread of which only summary statistics are known. The histogram has no bins; when n is known every cycle
// counts as beyond its (empty) range, so cycles == bins + overflows still holds and nothing claims a distribution;
// when n is not known cycles stays 0. min / max are the true extremes.
headroom::ThreadLatency summary_only_thread(int index, std::optional<std::uint64_t> cycles,
                                            std::optional<std::int64_t> min_ns, std::optional<std::int64_t> max_ns,
                                            std::optional<double> mean_ns, std::optional<double> sd_ns);

// True for a thread built by summary_only_thread (no bins).
bool summary_only(const headroom::ThreadLatency& thread);

// A measurement with one phase named kImportedPhase, load unknown, tool and kind set, provenance naming the file.
headroom::HeadroomMeasurement imported_measurement(headroom::LatencyKind kind, std::string tool,
                                                   const std::string& file);

// The batch holding `m`; `m` must satisfy its bookkeeping (checked here: an importer bug otherwise, reported as
// InvalidValue naming the file).
ImportBatch batch_of(headroom::HeadroomMeasurement m, const std::string& file);

}  // namespace bs::headroom_import
