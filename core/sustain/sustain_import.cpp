// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_import.h"

#include "sustain/sustain_json.h"
#include "util/home_name.h"

namespace bs::sustain {

HomeBatch sustain_import(const SustainRun& run, const std::optional<PowerTrace>& power, const std::string& where) {
  HomeBatch out = measured_home(home_name(where, run.platform, run.provenance.date), kSustainFormat, power,
                                record_to_json(run).dump());
  out.batch.sustain_runs = {run};
  return out;
}

}  // namespace bs::sustain
