// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/sustained_runs.h"

namespace bs {

std::vector<SustainRun> sustained_runs_of(const Workspace& ws) {
  std::vector<SustainRun> out;
  for (auto& s : ws.sustain_runs()) out.push_back(std::move(s.run));
  return out;
}

}  // namespace bs
