// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/paper_tables.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "analysis/peaks/flag_notes.h"
#include "analysis/peaks/flops.h"

namespace bs {
namespace {

const char* const kDash = "\xE2\x80\x93";

std::string value(double flops, double scale, const Summary& at_peak) {
  char buf[96];
  if (at_peak.n > 1)
    std::snprintf(buf, sizeof buf, "%.2f \xC2\xB1 %.2f (n = %zu)", flops / scale, at_peak.sd / scale, at_peak.n);
  else
    std::snprintf(buf, sizeof buf, "%.2f", flops / scale);
  return buf;
}

// Best row per (device, column key) over every D and variant.
using Best = std::map<std::pair<std::string, std::string>, PeakRow>;

}  // namespace

ExportTable gpu_peak_table(std::span<const FlopsRun> runs) {
  Best best;
  std::vector<std::string> devices;
  std::map<std::string, double> reported;
  for (const PeakRow& r : peak_table(runs)) {
    if (r.device_kind != DeviceKind::Gpu) continue;
    if (std::find(devices.begin(), devices.end(), r.device) == devices.end()) devices.push_back(r.device);
    const std::string column = r.backend == "CUDA" ? "CUDA" : r.backend == "OpenCL" ? "OpenCL" : "other";
    auto& slot = best[{r.device, column}];
    if (r.peak.flops > slot.peak.flops) slot = r;
    if (r.reported_flops) reported[r.device] = *r.reported_flops;
  }
  ExportTable t;
  t.caption = "Peak single-precision throughput of the rotation kernel on the GPUs (TFLOPS)";
  t.label = "tab:gpu-peaks";
  t.header = {"Device", "OpenCL (TFLOPS)", "CUDA (TFLOPS)", "Reported (TFLOPS)"};
  FlagNotes notes;
  for (const std::string& d : devices) {
    std::vector<std::string> row{d};
    for (const char* column : {"OpenCL", "CUDA"}) {
      const auto it = best.find({d, column});
      row.push_back(it == best.end()
                        ? kDash
                        : notes.mark(value(it->second.peak.flops, 1e12, it->second.peak.at_peak), it->second.flags));
    }
    char rep[32];
    if (reported.count(d)) std::snprintf(rep, sizeof rep, "%.2f", reported[d] / 1e12);
    row.push_back(reported.count(d) ? rep : kDash);
    t.rows.push_back(std::move(row));
  }
  notes.add_to(t);
  return t;
}

ExportTable cpu_peak_table(std::span<const FlopsRun> runs) {
  std::vector<PeakRow> best;
  for (const PeakRow& r : peak_table(runs)) {
    if (r.device_kind != DeviceKind::Cpu) continue;
    auto it = std::find_if(best.begin(), best.end(), [&](const PeakRow& b) { return b.device == r.device; });
    if (it == best.end())
      best.push_back(r);
    else if (r.peak.flops > it->peak.flops)
      *it = r;
  }
  ExportTable t;
  t.caption = "Peak single-precision throughput of the rotation kernel on the CPUs (GFLOPS)";
  t.label = "tab:cpu-peaks";
  t.header = {"Device", "Peak (GFLOPS)", "Instruction set / backend"};
  FlagNotes notes;
  for (const PeakRow& r : best)
    t.rows.push_back({r.device, notes.mark(value(r.peak.flops, 1e9, r.peak.at_peak), r.flags), r.backend});
  notes.add_to(t);
  return t;
}

}  // namespace bs
