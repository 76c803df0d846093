// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The platform a power log belongs to when the file does not say (issue #32.3): an Otii or meter export names no
// machine, and a log without a platform was a blank row that could win "best" in the Platforms table. The guess
// comes from the file's metadata (its host name or a platform-like setting), else from the workspace (its only
// platform), else a name that says so ("unassigned: <log>"): never blank. The GUI asks with the guess filled in;
// `benchscope-cli import --platform NAME` gives it; the platform can be changed later (tree > Platform…).
#include <string>
#include <vector>

#include "model/power_trace.h"

namespace bs {

struct LogPlatformGuess {
  std::string platform;  // never blank
  std::string how;       // "the file's host name", "the workspace's only platform", ...
};

// `known`: the platforms the workspace has (a guess matching one of them, ignoring case, takes its spelling).
LogPlatformGuess infer_log_platform(const PowerTrace& trace, const std::vector<std::string>& known);
// The same for any imported result whose file names no platform (a cyclictest or rttest file): from what its
// provenance says of the machine, else the workspace's only platform, else "unassigned: <label>".
LogPlatformGuess infer_platform(const Provenance& provenance, const std::string& label,
                                const std::vector<std::string>& known);

bool blank_platform(const std::string& name);

}  // namespace bs
