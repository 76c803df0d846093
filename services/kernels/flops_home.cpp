// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/flops_home.h"

#include <stdexcept>

#include "runs/run_json.h"
#include "store/workspace.h"
#include "util/home_name.h"

namespace bs {

HomeBatch flops_home(const std::vector<FlopsRun>& runs, const std::optional<PowerTrace>& power,
                     const std::string& where) {
  if (runs.empty()) throw std::invalid_argument(where + ": a sweep with no run has nothing to store");
  HomeBatch out;
  out.batch.source_path = home_name(where, runs.front().platform, runs.front().provenance.date);
  out.batch.format = std::string(kRunJsonFileFormat.id);
  out.batch.runs = runs;
  if (power) out.batch.power_traces.push_back(*power);
  out.content_hash = content_hash(write_run_json(runs));
  return out;
}

}  // namespace bs
