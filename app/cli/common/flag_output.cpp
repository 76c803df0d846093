// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/flag_output.h"

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
          {"url", spec->source_url},
          {"unverified", spec->unverified}};
}

std::vector<PlausibilityFlag> throughput_flags(const ResultSet& set, const Measurement& m, double value) {
  if (m.unit != "FLOP/s" || m.metric.rfind("single-precision", 0) != 0) return {};
  const BundledDeviceTable& table = bundled_device_table();
  return check_flops(value, match_device(table.table, set.device, set.device_kind, set.platform));
}

void print_flag_notes(std::ostream& out, const FlagNotes& notes) {
  if (notes.empty()) return;
  out << "\nFlags (implausible numbers; docs/cli.md, \"Plausibility flags\"):\n";
  for (const std::string& line : notes.lines()) out << "  " << line << '\n';
}

}  // namespace bs::cli
