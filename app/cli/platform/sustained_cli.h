// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sustained requirement's verdicts (sustain/sustain_requirement.h) for a terminal and as JSON, in
// `platforms --require-sustained` (and the stored requirement the workspace's Platforms tab set).
#include <iosfwd>
#include <vector>

#include <nlohmann/json.hpp>

#include "sustain/sustain_requirement.h"

namespace bs::cli {

// {"requirement", "described", "platforms": [{platform, status, margin, reason, record, checks}]}.
nlohmann::json sustained_json(const sustain::SustainRequirement& r, const std::vector<sustain::SustainVerdict>& v);
// One row per platform, ranked: verdict, margin or reason, the record that judged it.
void print_sustained(std::ostream& out, const sustain::SustainRequirement& r,
                     const std::vector<sustain::SustainVerdict>& v);

}  // namespace bs::cli
