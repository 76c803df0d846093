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
  HomeBatch out = measured_home(home_name(where, runs.front().platform, runs.front().provenance.date),
                                std::string(kRunJsonFileFormat.id), power, write_run_json(runs));
  out.batch.runs = runs;
  return out;
}

}  // namespace bs
