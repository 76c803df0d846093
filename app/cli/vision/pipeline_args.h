// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The detection options shared by `pipeline` and `bench pipeline`: how many detection workers and at what scale
// the detector sees the frame. Read by the pipeline grammar (core/commands/pipeline_grammar.h); bad values are
// UsageErrors naming the option and the accepted range.
#include <cstddef>

#include "commands/pipeline_grammar.h"
#include "common/args.h"
#include "vision/pipeline/pipeline.h"

namespace bs::cli {

// --detect-workers W: a whole number from 1 to vision::kMaxDetectionWorkers; default this machine's threads.
inline std::size_t detect_workers_option(const ParsedArgs& args) {
  return commands::read_detect_workers(args).value_or(vision::default_detection_workers());
}
// --detect-scale S: 0 < S <= 1; default 0.5 (HOG on a half-size frame, as the pipeline always did).
inline double detect_scale_option(const ParsedArgs& args) { return commands::read_detect_scale(args); }

}  // namespace bs::cli
