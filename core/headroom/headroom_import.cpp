// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_import.h"

#include "headroom/headroom_json.h"
#include "store/workspace.h"
#include "util/home_name.h"

namespace bs::headroom {

HomeBatch headroom_import(const HeadroomMeasurement& m, const std::optional<PowerTrace>& power,
                          const std::string& where) {
  HomeBatch out;
  out.batch.source_path = home_name(where, m.platform, m.provenance.date);
  out.batch.format = kHeadroomFormat;
  out.batch.headroom = {m};
  if (power) out.batch.power_traces.push_back(*power);
  out.content_hash = content_hash(to_json(m).dump());
  return out;
}

}  // namespace bs::headroom
