// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli peaks: the paper's Tables 1 and 2 (peak FLOPS per device, backend and D) from a workspace or files.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/flops.h"
#include "analysis/units.h"
#include "args.h"
#include "command.h"
#include "flag_output.h"
#include "inputs.h"
#include "signals.h"
#include "text_table.h"

namespace bs::cli {
namespace {

using nlohmann::json;

struct ThroughputPeak {
  const ResultSet* set;
  const Measurement* measurement;
  double value;
};

// The best FLOP/s figure of each result set (clpeak's widest vector type, a benchmark's FLOPS counter).
std::vector<ThroughputPeak> throughput_peaks(const std::vector<ResultSet>& sets) {
  std::vector<ThroughputPeak> out;
  for (const ResultSet& s : sets) {
    std::optional<ThroughputPeak> best;
    for (const Measurement& m : s.measurements) {
      if (m.unit != "FLOP/s") continue;
      for (double v : m.values)
        if (!best || v > best->value) best = ThroughputPeak{&s, &m, v};
    }
    if (best) out.push_back(*best);
  }
  return out;
}

json optional_number(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json peaks_json(const std::vector<PeakRow>& rows, const std::vector<ThroughputPeak>& throughput) {
  json jrows = json::array();
  for (const PeakRow& r : rows)
    jrows.push_back({{"platform", r.platform},
                     {"device", r.device},
                     {"device_kind", std::string(to_string(r.device_kind))},
                     {"backend", r.backend},
                     {"variant", r.variant},
                     {"dims", r.dims},
                     {"iterations", r.iterations},
                     {"peak_flops", r.peak.flops},
                     {"workers_at_peak", r.peak.workers},
                     {"n", r.peak.at_peak.n},
                     {"sd_flops", r.peak.at_peak.sd},
                     {"reported_flops", optional_number(r.reported_flops)},
                     {"ratio_to_reported", optional_number(r.ratio_to_reported)},
                     {"theoretical_flops", optional_number(r.theoretical_flops)},
                     {"fraction_of_theoretical", optional_number(r.fraction_of_theoretical)},
                     {"spec", spec_json(r.spec)},
                     {"fraction_of_spec", optional_number(r.fraction_of_spec)},
                     {"origin", std::string(to_string(r.origin))},
                     {"source_file", r.source_file},
                     {"flags", flags_json(r.flags)}});
  json jt = json::array();
  for (const ThroughputPeak& t : throughput)
    jt.push_back({{"platform", t.set->platform},
                  {"device", t.set->device},
                  {"backend", t.set->backend},
                  {"source_format", t.set->source_format},
                  {"name", t.measurement->name},
                  {"metric", t.measurement->metric},
                  {"value", t.value},
                  {"unit", t.measurement->unit},
                  {"flags", flags_json(throughput_flags(*t.set, *t.measurement, t.value))}});
  const BundledDeviceTable& table = bundled_device_table();
  return {{"format", "benchscope-peaks"},
          {"version", 1},
          {"device_table", {{"path", table.table.path}, {"devices", table.table.devices.size()}, {"error", table.error}}},
          {"rows", jrows},
          {"throughput", jt}};
}

std::string ratio_text(const std::optional<double>& r) {
  if (!r) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2fx", *r);
  return buf;
}

std::string percent_text(const std::optional<double>& f) {
  if (!f) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %%", *f * 100.0);
  return buf;
}

void print_human(std::ostream& out, const std::vector<PeakRow>& rows, const std::vector<ThroughputPeak>& throughput) {
  TextTable table({"Platform", "Device", "Kind", "Backend", "Variant", "D", "Peak", "Workers at peak", "n",
                   "Reported", "Ratio", "% of theor.", "% of spec", "Origin", "Flags"});
  FlagNotes notes;
  for (const PeakRow& r : rows) {
    std::string peak = format_si(r.peak.flops, "FLOPS");
    if (r.peak.at_peak.n > 1) peak += " \xC2\xB1 " + format_si(r.peak.at_peak.sd, "FLOPS");
    table.add({r.platform, r.device, std::string(to_string(r.device_kind)), r.backend, r.variant,
               std::to_string(r.dims), peak, std::to_string(r.peak.workers), std::to_string(r.peak.at_peak.n),
               r.reported_flops ? format_si(*r.reported_flops, "FLOPS") : "-", ratio_text(r.ratio_to_reported),
               percent_text(r.fraction_of_theoretical), percent_text(r.fraction_of_spec),
               std::string(to_string(r.origin)), notes.marker(r.flags)});
  }
  if (table.empty()) {
    out << "no FLOPS runs\n";
  } else {
    out << "Peak FLOPS (6*D*N*W/t); % of spec: of the vendor's FP32 peak (device table)\n";
    table.print(out);
    print_flag_notes(out, notes);
  }
  if (!throughput.empty()) {
    TextTable t({"Platform", "Device", "Backend", "Source", "Measurement", "Peak"});
    for (const ThroughputPeak& p : throughput)
      t.add({p.set->platform, p.set->device, p.set->backend, p.set->source_format,
             p.measurement->metric + " / " + p.measurement->name, format_si(p.value, "FLOPS")});
    out << "\nThroughput results (FLOP/s measurements from other tools)\n";
    t.print(out);
  }
}

int run_peaks(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--kind"});
  if (args.positional.empty()) throw UsageError("peaks needs a workspace or files/folders");
  LoadedData data = load_inputs(args.positional, interrupt_token());
  if (const auto kind = args.value("--kind")) {
    if (*kind != "cpu" && *kind != "gpu") throw UsageError("--kind must be cpu or gpu");
    const DeviceKind k = device_kind_from_string(*kind);
    std::erase_if(data.runs, [&](const FlopsRun& r) { return r.device_kind != k; });
    std::erase_if(data.result_sets, [&](const ResultSet& s) { return s.device_kind != k; });
  }
  const std::vector<PeakRow> rows = peak_table(data.runs);
  const std::vector<ThroughputPeak> throughput = throughput_peaks(data.result_sets);
  if (args.has("--json"))
    out << peaks_json(rows, throughput).dump(2) << '\n';
  else
    print_human(out, rows, throughput);
  return 0;
}

const CommandRegistrar registrar({
    "peaks",
    "peak FLOPS table (paper Tables 1 and 2) of a workspace or of files",
    "usage: benchscope-cli peaks (WORKSPACE | PATH...) [--json] [--kind cpu|gpu]\n"
    "  Prints, per run, the highest mean FLOPS (6*D*N*W/t), the workers where it occurs, the reported figure and\n"
    "  the ratio to it. With --json: {\"format\":\"benchscope-peaks\",\"version\":1,\"rows\":[...],\n"
    "  \"throughput\":[...]} as documented in docs/cli.md.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        return run_peaks(args, out);
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << "\nusage: benchscope-cli peaks (WORKSPACE | PATH...) [--json]\n";
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
