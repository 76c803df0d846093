// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/stats/measurement_text.h"

namespace bs {

std::string measurement_text(const Provenance& p) {
  if (p.measurement == MeasurementKind::Unknown)
    return p.sensor.empty() ? "unknown (the source does not say)" : "unknown: " + p.sensor;
  std::string s(to_string(p.measurement));
  if (!p.sensor.empty()) s += ": " + p.sensor;
  return s;
}

}  // namespace bs
