// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline_args.h"

#include <cmath>
#include <string>

#include "vision/pipeline/pipeline.h"

namespace bs::cli {

std::size_t detect_workers_option(const ParsedArgs& args) {
  const auto fallback = static_cast<double>(vision::default_detection_workers());
  const double w = args.number("--detect-workers", fallback);
  const auto max = static_cast<double>(vision::kMaxDetectionWorkers);
  if (!(w >= 1 && w <= max) || w != std::floor(w))
    throw UsageError("--detect-workers must be a whole number from 1 to " +
                     std::to_string(vision::kMaxDetectionWorkers) + " (got '" +
                     args.value("--detect-workers").value_or("") + "')");
  return static_cast<std::size_t>(w);
}

double detect_scale_option(const ParsedArgs& args) {
  const double s = args.number("--detect-scale", 0.5);
  if (!(s > 0 && s <= 1))
    throw UsageError(
        "--detect-scale must be greater than 0 and at most 1, the factor the frame is shrunk by before "
        "detection (got '" +
        args.value("--detect-scale").value_or("") + "')");
  return s;
}

}  // namespace bs::cli
