// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How inference runs measured in-process go home (#52's one way home, for this kind): `benchscope-cli bench dnn
// --workspace` stores the runs of one bench (one per network and target) as one import through this builder, as
// any front end that measures inference must, so the same bench is recognised as the same import.
#include <optional>
#include <string>
#include <vector>

#include "model/dnn_run.h"
#include "model/power_trace.h"
#include "store/home_batch.h"

namespace bs {

inline constexpr const char* kDnnFormat = "benchscope-dnn-v1";

// `runs`: at least one (std::invalid_argument otherwise); `where`: who measured them, for the import's name
// ("benchscope-cli bench dnn"; util/home_name.h, with the first run's platform and date). The content hash is of
// each run's model hash, target, date and mean forward time (no file format writes inference runs). The power trace
// recorded beside the bench goes into the same import.
HomeBatch dnn_home(const std::vector<DnnRun>& runs, const std::optional<PowerTrace>& power, const std::string& where);

}  // namespace bs
