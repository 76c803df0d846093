// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/dnn_home.h"

#include <stdexcept>

#include "store/workspace.h"
#include "util/home_name.h"
#include "util/text.h"

namespace bs {

HomeBatch dnn_home(const std::vector<DnnRun>& runs, const std::optional<PowerTrace>& power, const std::string& where) {
  if (runs.empty()) throw std::invalid_argument(where + ": a bench with no run has nothing to store");
  HomeBatch out;
  out.batch.source_path = home_name(where, runs.front().platform, runs.front().provenance.date);
  out.batch.format = kDnnFormat;
  out.batch.dnn_runs = runs;
  if (power) out.batch.power_traces.push_back(*power);
  std::string key;
  for (const DnnRun& r : runs) key += r.model_hash + r.backend + r.provenance.date + fixed(r.forward.mean_s, 9);
  out.content_hash = content_hash(key);
  return out;
}

}  // namespace bs
