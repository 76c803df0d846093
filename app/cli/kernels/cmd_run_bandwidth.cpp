// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli run bandwidth: STREAM triad on a CPU or OpenCL backend, the roofline's memory ceiling.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/stats/stats.h"
#include "analysis/stats/units.h"
#include "commands/run_bandwidth_grammar.h"
#include "common/args.h"
#include "common/signals.h"
#include "kernels/ceilings/bandwidth.h"
#include "kernels/measured_set_home.h"
#include "store/home_batch.h"
#include "store/workspace.h"

namespace bs::cli {

int run_bandwidth(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  if (raw.empty() || raw[0] != "bandwidth") throw UsageError("expected 'run bandwidth'");
  const commands::RunBandwidthSettings args = commands::run_bandwidth_from_words({raw.begin() + 1, raw.end()});
  kernels::BandwidthSpec spec;
  spec.mib_per_array = args.mib_per_array;
  spec.repeats = args.repeats;

  const kernels::CpuInfo cpu = kernels::detect_cpu();
  const auto backends = kernels::available_backends(cpu);
  std::string backend_id = args.backend;
  if (const auto device = args.device) backend_id += ":" + *device;
  const kernels::Backend* backend = nullptr;
  try {
    backend = &kernels::find_backend(backends, backend_id);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (!backend->run_triad) throw UsageError(backend->label + " has no bandwidth kernel (use cpu or opencl)");
  const bool quiet = args.quiet;
  if (!quiet)
    err << "benchscope-cli: STREAM triad on " << backend->label << " (" << backend->device_name << "), 3 x "
        << spec.mib_per_array << " MiB, " << spec.repeats << " repetitions\n";
  ResultSet set;
  try {
    set = kernels::measure_bandwidth(*backend, cpu, spec, interrupt_token());
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const Measurement& m = set.measurements.front();
  const Summary s = summarize(m.values);
  if (const auto ws_path = args.workspace) {
    bring_home(*ws_path, measured_set_home(set, "benchscope-cli run bandwidth"));
    if (!quiet) err << "benchscope-cli: stored in " << *ws_path << '\n';
  }
  if (args.json) {
    out << nlohmann::json{{"format", "benchscope-bandwidth"},
                          {"version", 1},
                          {"platform", set.platform},
                          {"device", set.device},
                          {"backend", set.backend},
                          {"kernel", "stream-triad"},
                          {"bytes_per_element", kernels::kTriadBytesPerElement},
                          {"mib_per_array", spec.mib_per_array},
                          {"bytes_per_second", m.values},
                          {"mean", s.mean},
                          {"sd", s.sd},
                          {"max", s.max}}
               .dump(2)
        << '\n';
  } else {
    const double scale = 1e9;
    out << backend->label << " (" << backend->device_name << "): STREAM triad "
        << format_mean_sd(s.mean / scale, s.sd / scale, s.n, "GB/s", 2) << ", best " << format_si(s.max, "B/s", 2)
        << "\n  roofline ridge point at this bandwidth: ";
    char line[160];
    if (backend->theoretical_peak_flops > 0)
      std::snprintf(line, sizeof line, "%.2f FLOP/byte (%s / %s)\n", backend->theoretical_peak_flops / s.max,
                    format_si(backend->theoretical_peak_flops, "FLOPS").c_str(), format_si(s.max, "B/s").c_str());
    else
      std::snprintf(line, sizeof line, "unknown (no theoretical peak for this device)\n");
    out << line;
  }
  return 0;
}

}  // namespace bs::cli
