// SPDX-License-Identifier: GPL-3.0-or-later
#include "flag_output.h"

#include <algorithm>
#include <ostream>

namespace bs::cli {

nlohmann::json flags_json(const std::vector<PlausibilityFlag>& flags) {
  nlohmann::json out = nlohmann::json::array();
  for (const PlausibilityFlag& f : flags) out.push_back({{"code", f.code}, {"reason", f.reason}});
  return out;
}

nlohmann::json spec_json(const std::optional<DeviceSpec>& spec) {
  if (!spec) return nullptr;
  auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  return {{"id", spec->id},
          {"name", spec->name},
          {"fp32_peak_flops", spec->fp32_peak_flops},
          {"derivation", spec->derivation},
          {"memory_bandwidth_bytes_per_s", opt(spec->memory_bandwidth_bytes_per_s)},
          {"tdp_w", opt(spec->tdp_w)},
          {"source", spec->source_title},
          {"url", spec->source_url}};
}

std::string FlagNotes::marker(const std::vector<PlausibilityFlag>& flags) {
  std::string text;
  for (const PlausibilityFlag& f : flags) {
    auto it = std::find(notes_.begin(), notes_.end(), f);
    if (it == notes_.end()) it = notes_.insert(notes_.end(), f);
    text += (text.empty() ? "\xE2\x9A\xA0 " : ",") + std::to_string(it - notes_.begin() + 1);
  }
  return text;
}

void FlagNotes::print(std::ostream& out) const {
  if (notes_.empty()) return;
  out << "\nFlags (implausible numbers; docs/cli.md, \"Plausibility flags\"):\n";
  for (std::size_t i = 0; i < notes_.size(); ++i)
    out << "  [" << i + 1 << "] " << notes_[i].code << ": " << notes_[i].reason << '\n';
}

}  // namespace bs::cli
