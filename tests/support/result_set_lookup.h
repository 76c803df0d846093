// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Looking into what an importer made of a source: a measurement of a result set by its name and metric, and what it
// kept of the source's own settings (Provenance::settings: a run's flags, a library's build type).
#include <string>

#include "model/flops_run.h"
#include "model/provenance.h"

namespace bs::test {

// The measurement named `name` with metric `metric`, or null.
inline const Measurement* find_measurement(const ResultSet& s, const std::string& name, const std::string& metric) {
  for (const auto& m : s.measurements)
    if (m.name == name && m.metric == metric) return &m;
  return nullptr;
}

// The value kept under `key`, or "(absent)", a value no test expects, so a setting that was not kept fails a
// comparison.
inline std::string setting(const Provenance& p, const std::string& key) {
  for (const auto& [k, v] : p.settings)
    if (k == key) return v;
  return "(absent)";
}

inline std::string setting(const ResultSet& s, const std::string& key) { return setting(s.provenance, key); }

}  // namespace bs::test
