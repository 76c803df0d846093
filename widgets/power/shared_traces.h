// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The workspace's power traces with their samples, loaded once and shared by every view that reads samples (Power,
// Efficiency, Battery, Platforms). A 4 kS/s meter over 7 hours is 100 million samples, 1.6 GB of time and current:
// a copy per view (and a per-sample power series and index copy in the Power tab) took 9.6 GB to view such a log.
// Views hold this pointer instead; the Power tab's indexes read the samples in place (PowerIndex's shared form).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "store/workspace.h"

namespace bs::ui {

struct LoadedTraces {
  std::vector<PowerTrace> traces;
  std::vector<std::int64_t> ids;  // the workspace id of each trace (0: not stored in a workspace)
};
using SharedTraces = std::shared_ptr<const LoadedTraces>;

// Moves the traces (and their samples) in: nothing is copied.
SharedTraces share_traces(std::vector<StoredPowerTrace> stored);
SharedTraces share_traces(std::vector<PowerTrace> traces);
// Trace i, keeping the whole set alive as long as the pointer lives (shared_ptr's aliasing constructor).
std::shared_ptr<const PowerTrace> trace_of(const SharedTraces& set, std::size_t i);

}  // namespace bs::ui
