// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_import.h"

#include "headroom/headroom_json.h"
#include "util/home_name.h"

namespace bs::headroom {

HomeBatch headroom_import(const HeadroomMeasurement& m, const std::optional<PowerTrace>& power,
                          const std::string& where) {
  HomeBatch out =
      measured_home(home_name(where, m.platform, m.provenance.date), kHeadroomFormat, power, to_json(m).dump());
  out.batch.headroom = {m};
  return out;
}

}  // namespace bs::headroom
