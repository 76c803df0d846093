// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli peaks: the paper's Tables 1 and 2 (peak FLOPS per device, backend and D) from a workspace or files.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/peaks/flops.h"
#include "analysis/peaks/peak_ceilings.h"
#include "analysis/peaks/result_peaks.h"
#include "analysis/stats/units.h"
#include "common/args.h"
#include "common/command.h"
#include "common/flag_output.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

using nlohmann::json;

json optional_number(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

// FLOP/s for floating point, operations/s for integer formats ("1/s" in the model).
std::string rate_unit(const Measurement& m) { return m.unit == "FLOP/s" ? "FLOPS" : "OPS"; }

json peaks_json(const std::vector<PeakRow>& rows, const std::vector<ResultPeak>& throughput) {
  json jrows = json::array();
  for (const PeakRow& r : rows)
    jrows.push_back({{"platform", r.platform},
                     {"device", r.device},
                     {"device_kind", std::string(to_string(r.device_kind))},
                     {"backend", r.backend},
                     {"variant", r.variant},
                     {"dims", r.dims > 0 ? json(r.dims) : json(nullptr)},
                     {"iterations", r.iterations > 0 ? json(r.iterations) : json(nullptr)},
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
                     {"empirical_ceiling_flops", optional_number(r.empirical_ceiling_flops)},
                     {"fraction_of_ceiling", optional_number(r.fraction_of_ceiling)},
                     {"origin", std::string(to_string(r.origin))},
                     {"source_file", r.source_file},
                     {"flags", flags_json(r.flags)}});
  json jt = json::array();
  for (const ResultPeak& t : throughput)
    jt.push_back({{"platform", t.set->platform},
                  {"device", t.set->device},
                  {"backend", t.set->backend},
                  {"source_format", t.set->source_format},
                  {"name", t.measurement->name},
                  {"metric", t.measurement->metric},
                  {"precision", std::string(to_string(t.cls.precision))},
                  {"kind", std::string(to_string(t.cls.kind))},
                  {"value", t.summary.mean},
                  {"n", t.summary.n},
                  {"sd", t.summary.sd},
                  {"unit", t.measurement->unit},
                  {"flags", flags_json(throughput_flags(*t.set, *t.measurement, t.summary.mean))}});
  const BundledDeviceTable& table = bundled_device_table();
  return {
      {"format", "benchscope-peaks"},
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

void print_human(std::ostream& out, const std::vector<PeakRow>& rows, const std::vector<ResultPeak>& throughput,
                 const ResultPeakQuery& query, std::size_t left_out) {
  TextTable table({"Platform", "Device", "Kind", "Backend", "Variant", "D", "Peak", "Workers at peak", "n", "Reported",
                   "Ratio", "% of theor.", "% of spec", "Origin", "Flags"});
  FlagNotes notes;
  for (const PeakRow& r : rows) {
    std::string peak = format_si(r.peak.flops, "FLOPS");
    if (r.peak.at_peak.n > 1) peak += " \xC2\xB1 " + format_si(r.peak.at_peak.sd, "FLOPS");
    // A sweep from another tool states FLOPS, not D and N: "-".
    table.add({r.platform, r.device, std::string(to_string(r.device_kind)), r.backend, r.variant,
               r.dims > 0 ? std::to_string(r.dims) : "-", peak, std::to_string(r.peak.workers),
               std::to_string(r.peak.at_peak.n), r.reported_flops ? format_si(*r.reported_flops, "FLOPS") : "-",
               ratio_text(r.ratio_to_reported), percent_text(r.fraction_of_theoretical),
               percent_text(r.fraction_of_spec), std::string(to_string(r.origin)), notes.marker(r.flags)});
  }
  if (table.empty()) {
    out << "no FLOPS runs\n";
  } else {
    out << "Peak FLOPS (6*D*N*W/t); % of spec: of the vendor's FP32 peak (device table)\n";
    table.print(out);
    print_flag_notes(out, notes);
  }
  if (!throughput.empty()) {
    TextTable t({"Platform", "Device", "Backend", "Source", "Precision", "Measurement", "Peak", "n"});
    for (const ResultPeak& p : throughput) {
      std::string peak = format_si(p.summary.mean, rate_unit(*p.measurement));
      if (p.summary.n > 1) peak += " \xC2\xB1 " + format_si(p.summary.sd, rate_unit(*p.measurement));
      std::string precision(precision_label(p.cls.precision));
      if (!query.precision && p.cls.kind != MeasureKind::VectorCompute)
        precision += std::string(" ") + std::string(to_string(p.cls.kind));
      t.add({p.set->platform, p.set->device, p.set->backend, p.set->source_format, precision,
             p.measurement->metric + " / " + p.measurement->name, peak, std::to_string(p.summary.n)});
    }
    out << "\nThroughput results from other tools ("
        << (query.precision ? std::string(precision_label(*query.precision)) + " vector compute"
                            : std::string("every precision, one row each"))
        << ")\n";
    t.print(out);
  }
  if (left_out > 0)
    out << left_out << " compute result(s) of other precisions or kinds not shown (--precision all lists them)\n";
}

int run_peaks(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--kind", "--precision"});
  if (args.positional.empty()) throw UsageError("peaks needs a workspace or files/folders");
  LoadedData data = load_inputs(args.positional, interrupt_token());
  if (const auto kind = args.value("--kind")) {
    if (*kind != "cpu" && *kind != "gpu") throw UsageError("--kind must be cpu or gpu");
    const DeviceKind k = device_kind_from_string(*kind);
    std::erase_if(data.runs, [&](const FlopsRun& r) { return r.device_kind != k; });
    std::erase_if(data.result_sets, [&](const ResultSet& s) { return s.device_kind != k; });
  }
  // Against the devices' empirical ceilings stored with the data (result sets of "benchscope-ceilings"); a peak
  // above its computed peak is flagged either way.
  std::vector<PeakRow> rows = peak_table(data.runs);
  apply_empirical_ceilings(rows, data.result_sets);
  ResultPeakQuery query;  // FP32 vector compute, as the paper compares
  if (const auto p = args.value("--precision")) {
    if (*p == "all") {
      query.precision.reset();
    } else if (const auto precision = precision_from_string(*p)) {
      query.precision = *precision;
    } else {
      throw UsageError(
          "--precision must be fp32 (single), fp64 (double), fp16 (half), bf16, tf32, mixed, fp8, fp4, "
          "int64, int32, int24, int16, int8, int4 or all; got '" +
          *p + "'");
    }
  }
  const std::vector<ResultPeak> throughput = result_peaks(data.result_sets, query);
  if (args.has("--json"))
    out << peaks_json(rows, throughput).dump(2) << '\n';
  else
    print_human(out, rows, throughput, query, compute_measurements_left_out(data.result_sets, query));
  return 0;
}

const CommandRegistrar registrar({
    "peaks",
    "peak FLOPS table (paper Tables 1 and 2) of a workspace or of files",
    "usage: benchscope-cli peaks (WORKSPACE | PATH...) [--json] [--kind cpu|gpu] [--precision P|all]\n"
    "  Prints, per run, the highest mean FLOPS (6*D*N*W/t), the workers where it occurs, the reported figure and\n"
    "  the ratio to it; then, per device of clpeak / Google Benchmark results, its peak of one precision:\n"
    "  fp32 (single, the default, as the paper), fp64, fp16, bf16, tf32, mixed, fp8, fp4, int32, int24, int16,\n"
    "  int8, int4; 'all' gives one row per precision and kind. With --json: {\"format\":\"benchscope-peaks\",\n"
    "  \"version\":1,\"rows\":[...],\"throughput\":[...]} as documented in docs/cli.md.",
    out_only<run_peaks>,
});

}  // namespace
}  // namespace bs::cli
