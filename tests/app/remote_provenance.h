// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a run measured on a robot says it ran: the desk adds "remote host", "remote command", "remote architecture"
// ... to its provenance's settings when it brings the run home. The CLI's and the GUI's remote tests read them alike.
#include <string>

#include "model/provenance.h"

namespace bs::test {

// The value of the setting `key` in `p`: the first one so named, "" when there is none.
inline std::string setting(const Provenance& p, const std::string& key) {
  for (const auto& [k, v] : p.settings)
    if (k == key) return v;
  return {};
}

}  // namespace bs::test
