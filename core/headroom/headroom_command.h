// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The `benchscope-cli headroom` arguments that repeat a measurement on another computer: what the Headroom tab sends
// to a robot (`benchscope-cli remote ROBOT headroom ...`, issue #44) when its target is not this machine. Loads go
// as the CLI's --load syntax and an external command as --load-command: both are run by the robot's CLI, on the
// robot. Every setting is spelled out, defaults too, so the robot runs what the desk shows whatever its defaults.
#include <string>
#include <vector>

#include "headroom/headroom_run.h"

namespace bs::headroom {

// ["headroom", "--rate", "1000", "--seconds", "20", ...]; `loads` ("pipeline@30fps,dnn") and `load_command` ("stress-ng
// --cpu 2") may be empty; `record_power` adds "--power auto" (the robot's own sensors).
std::vector<std::string> headroom_cli_args(const RunConfig& config, const std::string& loads,
                                           const std::string& load_command, bool record_power);

}  // namespace bs::headroom
