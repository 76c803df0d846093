// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a vision pipeline run measured in-process goes home (#52's one way home, for this kind): the Pipeline tab and
// `benchscope-cli pipeline --workspace` build the same import with the same content-hash recipe, so the same run is
// recognised as the same import whichever front end stored it.
#include <optional>
#include <string>

#include "model/pipeline_run.h"
#include "model/power_trace.h"
#include "store/home_batch.h"

namespace bs {

// `where`: who measured it, for the import's name ("Pipeline tab", "benchscope-cli pipeline"; util/home_name.h). The
// content hash is of the run's pipeline JSON (write_pipeline_json). The power trace recorded beside the run goes
// into the same import, so it is stored and removed with the run.
HomeBatch pipeline_home(const PipelineRun& run, const std::optional<PowerTrace>& power, const std::string& where);

}  // namespace bs
