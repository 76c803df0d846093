// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a FLOPS sweep measured in-process goes home (#52's one way home, for this kind): the Kernel Runner
// (MainWindow::store_measured_runs) and `benchscope-cli run flops --workspace` build the same import with the same
// content-hash recipe, so the same sweep is recognised as the same import whichever front end stored it.
#include <optional>
#include <string>
#include <vector>

#include "model/flops_run.h"
#include "model/power_trace.h"
#include "store/home_batch.h"

namespace bs {

// `runs`: the sweep's runs, at least one (std::invalid_argument otherwise); `where`: who measured it, for the
// import's name ("Kernel Runner", "benchscope-cli run flops"; util/home_name.h, with the first run's platform and
// date). The content hash is of the runs' run JSON (write_run_json). The power trace recorded beside the sweep
// goes into the same import, so it is stored, listed and removed with the runs.
HomeBatch flops_home(const std::vector<FlopsRun>& runs, const std::optional<PowerTrace>& power,
                     const std::string& where);

}  // namespace bs
