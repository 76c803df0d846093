// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli devices: every backend/device the kernels can run on, with its theoretical peak.
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/units.h"
#include "args.h"
#include "command.h"
#include "kernels/backend.h"

namespace bs::cli {
namespace {

int run_devices(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {});
  const kernels::CpuInfo cpu = kernels::detect_cpu();
  const auto backends = kernels::available_backends(cpu);
  if (args.has("--json")) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& b : backends) {
      nlohmann::json variants = nlohmann::json::array();
      for (auto v : b.variants) variants.push_back(b.variant_label(v));
      list.push_back({{"backend", b.id}, {"label", b.label}, {"device", b.device_name},
                      {"kind", std::string(to_string(b.kind))}, {"variants", variants},
                      {"theoretical_peak_flops", b.theoretical_peak_flops}, {"details", b.details}});
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
  }
  for (const std::string& why : kernels::unavailable_backends()) out << "not available: " << why << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "devices",
    "list the backends and devices the kernels can run on, with theoretical peaks",
    "usage: benchscope-cli devices [--json]\n"
    "  Every backend and device (CPU SIMD, CPU scalar, each OpenCL device, each CUDA GPU) with its properties and\n"
    "  the rotation kernel's theoretical peak, then the backends this build knows but cannot run here and why.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& /*err*/) {
      return run_devices(args, out);
    },
});

}  // namespace
}  // namespace bs::cli
