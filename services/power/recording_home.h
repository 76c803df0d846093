// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a power recording made in-process on its own goes home (#52's one way home, for this kind): `benchscope-cli
// record-power --workspace` stores the trace through this builder, as any front end that records power alone must.
// A trace recorded beside a measurement goes home inside that measurement's import instead (flops_home,
// pipeline_home, headroom_import, ...).
#include <string>

#include "model/power_trace.h"
#include "store/home_batch.h"

namespace bs {

// `where`: who recorded it, for the import's name ("benchscope-cli record-power"; util/home_name.h, with the trace's
// platform and start date). The content hash is of the trace as a recording CSV (sensors/recording_csv.h): its
// samples, sensor, provenance and phases, so the same recording is the same import.
HomeBatch recording_home(const PowerTrace& trace, const std::string& where);

}  // namespace bs
