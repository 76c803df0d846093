// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/dnn_home.h"

#include <stdexcept>

#include "store/workspace.h"
#include "util/home_name.h"
#include "util/text.h"

namespace bs {

HomeBatch dnn_home(const std::vector<DnnRun>& runs, const std::optional<PowerTrace>& power, const std::string& where) {
  if (runs.empty()) throw std::invalid_argument(where + ": a bench with no run has nothing to store");
  std::string key;
  for (const DnnRun& r : runs) key += r.model_hash + r.backend + r.provenance.date + fixed(r.forward.mean_s, 9);
  HomeBatch out =
      measured_home(home_name(where, runs.front().platform, runs.front().provenance.date), kDnnFormat, power, key);
  out.batch.dnn_runs = runs;
  return out;
}

}  // namespace bs
