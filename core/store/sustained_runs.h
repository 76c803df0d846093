// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sustained records a workspace holds (#53, schema 11), as the sustained requirement judges them
// (sustain/sustain_requirement.h): one place for the CLI's loader, the GUI's Platforms tab and its report.
#include <vector>

#include "model/sustain_run.h"
#include "store/workspace.h"

namespace bs {

std::vector<SustainRun> sustained_runs_of(const Workspace& ws);

}  // namespace bs
