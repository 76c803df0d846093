// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Plausibility flags in CLI output: `"flags": [{"code", "reason"}]` in every --json; text tables mark a flagged row
// "[n]" with a numbered note under the table (FlagNotes, analysis/flag_notes.h; print_flag_notes()).
#include <iosfwd>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/peaks/device_table.h"
#include "analysis/peaks/flag_notes.h"
#include "analysis/peaks/plausibility.h"
#include "model/flops_run.h"

namespace bs::cli {

nlohmann::json flags_json(const std::vector<PlausibilityFlag>& flags);
// {"id", "name", "fp32_peak_flops", "derivation", "memory_bandwidth_bytes_per_s", "tdp_w", "source", "url"} or null.
nlohmann::json spec_json(const std::optional<DeviceSpec>& spec);

// Flags of another tool's FLOP/s figure (clpeak, Google Benchmark) against the device table's FP32 peak. Only
// single-precision measurements are checked (clpeak's "single-precision compute ..."): a half-precision figure may
// rightly be twice the FP32 peak, and a double-precision one has its own, lower peak.
std::vector<PlausibilityFlag> throughput_flags(const ResultSet& set, const Measurement& m, double value);

// "Flags (...):" and the notes, one a line; nothing when there are none.
void print_flag_notes(std::ostream& out, const FlagNotes& notes);

}  // namespace bs::cli
