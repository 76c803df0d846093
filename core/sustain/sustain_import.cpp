// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_import.h"

#include "store/workspace.h"
#include "sustain/sustain_json.h"
#include "util/home_name.h"

namespace bs::sustain {

HomeBatch sustain_import(const SustainRun& run, const std::optional<PowerTrace>& power, const std::string& where) {
  HomeBatch out;
  out.batch.source_path = home_name(where, run.platform, run.provenance.date);
  out.batch.format = kSustainFormat;
  out.batch.sustain_runs = {run};
  if (power) out.batch.power_traces.push_back(*power);
  out.content_hash = content_hash(record_to_json(run).dump());
  return out;
}

}  // namespace bs::sustain
