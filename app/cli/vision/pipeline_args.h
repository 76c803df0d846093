// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The detection options shared by `pipeline` and `bench pipeline`: how many detection workers and at what scale
// the detector sees the frame. Bad values are UsageErrors naming the option and the accepted range.
#include <cstddef>

#include "common/args.h"

namespace bs::cli {

// --detect-workers W: a whole number from 1 to vision::kMaxDetectionWorkers; default this machine's threads.
std::size_t detect_workers_option(const ParsedArgs& args);
// --detect-scale S: 0 < S <= 1; default 0.5 (HOG on a half-size frame, as the pipeline always did).
double detect_scale_option(const ParsedArgs& args);

}  // namespace bs::cli
