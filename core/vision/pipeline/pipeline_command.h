// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The `benchscope-cli pipeline --synthetic` arguments that repeat the Pipeline tab's measurement on another
// computer: what the tab sends to a robot (`benchscope-cli remote ROBOT pipeline --synthetic ...`, issue #44). The
// robot renders the same synthetic capture of the paper's camera itself, so no frame travels; every setting is
// spelled out, defaults too, so the robot runs what the desk shows whatever its own defaults are.
#include <string>
#include <vector>

#include "vision/pipeline/pipeline_measure.h"

namespace bs::vision {

// ["pipeline", "--synthetic", "--frames", "20", "--detect-workers", "4", ...]; `platform` may be empty;
// `record_power` adds "--power auto" (the robot's own sensors). Throws std::invalid_argument for a detector that is
// a model file: it lies on this computer, not on the robot.
std::vector<std::string> synthetic_pipeline_cli_args(const SyntheticPipelineOptions& options,
                                                     const std::string& platform, bool record_power);

}  // namespace bs::vision
