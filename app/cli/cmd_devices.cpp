// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli devices: every backend/device the kernels can run on, with its theoretical peak.
#include <iostream>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "analysis/units.h"
#include "analysis/device_table.h"
#include "args.h"
#include "command.h"
#include "flag_output.h"
#include "kernels/backend.h"

namespace bs::cli {
namespace {

// The device table itself (resources/devices/devices.json): every entry with its FP32 peak and source.
int print_spec_table(const DeviceTable& table, bool json, std::ostream& out) {
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const DeviceSpec& s : table.devices) {
      nlohmann::json e = spec_json(s);
      e["kind"] = std::string(to_string(s.kind));
      e["aliases"] = s.aliases;
      e["note"] = s.note;
      list.push_back(std::move(e));
    }
    out << nlohmann::json{{"format", "benchscope-device-specs"}, {"version", 1}, {"path", table.path}, {"devices", list}}
               .dump(2)
        << '\n';
    return 0;
  }
  out << "device table " << table.path << " (" << table.devices.size() << " devices)\n";
  for (const DeviceSpec& s : table.devices) {
    out << s.id << " (" << to_string(s.kind) << "): " << s.name << "\n    FP32 peak " << format_si(s.fp32_peak_flops, "FLOPS")
        << " = " << s.derivation;
    if (s.memory_bandwidth_bytes_per_s) out << "; memory " << format_si(*s.memory_bandwidth_bytes_per_s, "B/s");
    if (s.tdp_w) out << "; TDP " << format_si(*s.tdp_w, "W");
    out << "\n    source: " << s.source_title << (s.source_url.empty() ? "" : " <" + s.source_url + ">") << '\n';
    if (!s.note.empty()) out << "    note: " << s.note << '\n';
  }
  return 0;
}

int run_devices(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json", "--table"}, {});
  const BundledDeviceTable& specs = bundled_device_table();
  if (args.has("--table")) {
    if (!specs.error.empty()) throw std::runtime_error(specs.error);
    return print_spec_table(specs.table, args.has("--json"), out);
  }
  const auto spec_of = [&](const kernels::Backend& b) -> std::optional<DeviceSpec> {
    const DeviceSpec* s = match_device(specs.table, b.device_name, b.kind);
    return s ? std::optional<DeviceSpec>(*s) : std::nullopt;
  };
  const kernels::CpuInfo cpu = kernels::detect_cpu();
  const auto backends = kernels::available_backends(cpu);
  if (args.has("--json")) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& b : backends) {
      nlohmann::json variants = nlohmann::json::array();
      for (auto v : b.variants) variants.push_back(b.variant_label(v));
      list.push_back({{"backend", b.id}, {"label", b.label}, {"device", b.device_name},
                      {"kind", std::string(to_string(b.kind))}, {"variants", variants},
                      {"theoretical_peak_flops", b.theoretical_peak_flops}, {"details", b.details},
                      {"spec", spec_json(spec_of(b))}});
    }
    out << nlohmann::json{{"format", "benchscope-devices"},
                          {"version", 1},
                          {"devices", list},
                          {"unavailable", kernels::unavailable_backends()}}
               .dump(2)
        << '\n';
    return 0;
  }
  for (const auto& b : backends) {
    out << b.id << ": " << b.label << " on " << b.device_name << "\n    " << b.details << "\n    variants:";
    for (auto v : b.variants) out << ' ' << b.variant_label(v);
    out << "\n    theoretical peak " << format_si(b.theoretical_peak_flops, "FLOPS") << "\n";
    if (const auto s = spec_of(b))
      out << "    vendor FP32 peak " << format_si(s->fp32_peak_flops, "FLOPS") << " (" << s->name << ": "
          << s->derivation << ")\n";
  }
  for (const std::string& why : kernels::unavailable_backends()) out << "not available: " << why << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "devices",
    "list the backends and devices the kernels can run on, with theoretical peaks",
    "usage: benchscope-cli devices [--table] [--json]\n"
    "  Every backend and device (CPU SIMD, CPU scalar, each OpenCL device, each CUDA GPU) with its properties, the\n"
    "  rotation kernel's theoretical peak and the vendor FP32 peak from the device table, then the backends this\n"
    "  build knows but cannot run here and why. --table: the device table (resources/devices/devices.json) with\n"
    "  every entry's FP32 peak, derivation and source.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& /*err*/) {
      return run_devices(args, out);
    },
});

}  // namespace
}  // namespace bs::cli
