// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Names for runs in legends and tables that tell them apart only where needed: eight sweeps of one device read
// "AMD EPYC · CPU SIMD · D=4" eight times unless something is added. What is added is what differs between the
// runs that would read the same: the run's label (the user's name for it) always when it has one, then the first of
// date and time, host, and the run's own detail (N) that separates them, more of them if one is not enough, and a
// counter as the last resort. Runs that already read apart keep their plain name.
#include <string>
#include <vector>

#include "model/flops_run.h"

namespace bs {

struct RunIdentity {
  std::string base;    // what the view calls the series: "GTX1080Ti · CUDA · D=4"
  std::string label;   // the user's name for the run; empty: none
  std::string date;    // ISO 8601 date-time of the measurement ("2026-11-26T14:03:12Z"); may be empty
  std::string host;    // measuring host; may be empty
  std::string detail;  // one more thing that may differ, e.g. "N = 40000"; may be empty
};

std::vector<std::string> distinct_names(const std::vector<RunIdentity>& runs);

// What distinct_names() adds to each run's base: its label, then what else tells it from runs of the same base
// ("fan at 100 % (14:03)", "14:05"); "" where the run needs nothing added. For a table whose other columns already
// say the base (the peak table's platform, device, backend, D).
std::vector<std::string> distinguishing_parts(const std::vector<RunIdentity>& runs);

// The identity of a FLOPS run under `base` (date and host from its provenance, detail "N = <iterations>").
RunIdentity run_identity(const FlopsRun& run, std::string base, std::string label = {});

}  // namespace bs
