// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Plausibility flags in CLI output: `"flags": [{"code", "reason"}]` in every --json, and in text tables a "⚠ n"
// marker whose numbered footnote under the table gives the reason.
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/device_table.h"
#include "analysis/plausibility.h"

namespace bs::cli {

nlohmann::json flags_json(const std::vector<PlausibilityFlag>& flags);
// {"id", "name", "fp32_peak_flops", "derivation", "memory_bandwidth_bytes_per_s", "tdp_w", "source", "url"} or null.
nlohmann::json spec_json(const std::optional<DeviceSpec>& spec);

// Collects the flags of a text table's rows and numbers them; marker() gives a row's cell text ("" for none).
class FlagNotes {
 public:
  std::string marker(const std::vector<PlausibilityFlag>& flags);
  void print(std::ostream& out) const;  // "Flags:\n  [1] reason\n" ..., nothing when no row was flagged

 private:
  std::vector<PlausibilityFlag> notes_;
};

}  // namespace bs::cli
