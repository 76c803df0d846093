// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli roofline: what the GUI's Roofline tab shows, as text or JSON: each device's ceilings, the
// rotation kernel's runs at their peak, and the preprocessing stages of the pipeline runs placed by their
// modelled arithmetic intensity (analysis/stage_roofline.h) and measured time.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/peaks/flops.h"
#include "analysis/roofline/stage_roofline.h"
#include "analysis/stats/units.h"
#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/text_table.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

nlohmann::json point_json(const RooflinePoint& p) {
  return {{"label", p.label},           {"intensity", p.intensity},       {"achieved", p.flops},
          {"attainable", p.attainable}, {"fraction_of_roof", p.fraction}, {"memory_bound", p.memory_bound}};
}

int run_roofline(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {});
  if (args.positional.empty()) throw UsageError("roofline needs a workspace or files");
  const LoadedData data = load_inputs(args.positional, interrupt_token());
  const auto ceilings = roofline_ceilings(data.runs, data.result_sets);
  if (ceilings.empty()) throw std::runtime_error("no FLOPS runs: a roofline needs a compute ceiling");

  std::vector<std::pair<PeakRow, RooflinePoint>> rotation;
  for (const PeakRow& row : peak_table(data.runs))
    for (const RooflineCeiling& c : ceilings) {
      if (c.platform != row.platform || c.device != row.device) continue;
      if (row.dims <= 0) continue;  // another tool's sweep (Google Benchmark): its intensity is unknown
      const double intensity = rotation_intensity(row.dims, row.iterations);
      const double flop_count = rotation_flop_count(row.dims, row.iterations, row.peak.workers);
      rotation.emplace_back(row, place_on_roofline(c, row.device + " " + row.backend + " D=" + std::to_string(row.dims),
                                                   flop_count, flop_count / intensity, flop_count / row.peak.flops));
    }
  const StagePlacements stages = place_preprocessing(ceilings, data.pipeline_runs);

  if (args.has("--json")) {
    nlohmann::json cs = nlohmann::json::array(), rs = nlohmann::json::array(), ss = nlohmann::json::array();
    for (const RooflineCeiling& c : ceilings) {
      const auto ridge = c.ridge_intensity();
      cs.push_back({{"platform", c.platform},
                    {"device", c.device},
                    {"kind", std::string(to_string(c.kind))},
                    {"peak_flops", c.peak_flops},
                    {"peak_source", c.peak_source},
                    {"bandwidth_bps", c.bandwidth_bps ? nlohmann::json(*c.bandwidth_bps) : nlohmann::json(nullptr)},
                    {"bandwidth_source", c.bandwidth_source},
                    {"ridge_intensity", ridge ? nlohmann::json(*ridge) : nlohmann::json(nullptr)}});
    }
    for (const auto& [row, p] : rotation) {
      nlohmann::json j = point_json(p);
      j["platform"] = row.platform;
      j["device"] = row.device;
      j["backend"] = row.backend;
      rs.push_back(j);
    }
    for (const StagePlacement& s : stages.placed) {
      nlohmann::json j = point_json(s.point);
      j.update(
          {{"platform", s.platform},
           {"device", s.device},
           {"run_device", s.run_device},
           {"backend", s.backend},
           {"stage", pipeline_stage::kPreprocess},
           {"kernels", s.cost.label},
           {"geometry",
            {{"source", {s.geometry.source_width, s.geometry.source_height}},
             {"output", {s.geometry.output_width, s.geometry.output_height}},
             {"output_assumed_equal_to_source", s.geometry_assumed}}},
           {"ops_per_frame", s.cost.ops},
           {"bytes_per_frame", s.cost.bytes},
           {"ops_per_output_pixel", s.cost.ops_per_output_pixel},
           {"bytes_per_output_pixel", s.cost.bytes_per_output_pixel},
           {"time_s", {{"mean", s.time.mean_s}, {"sd", s.time.sd_s}, {"n", s.time.n}}},
           {"achieved_at_mean_plus_sd", s.ops_per_s_low ? nlohmann::json(*s.ops_per_s_low) : nlohmann::json(nullptr)},
           {"achieved_at_mean_minus_sd",
            s.ops_per_s_high ? nlohmann::json(*s.ops_per_s_high) : nlohmann::json(nullptr)},
           {"memory_ceiling_known", s.memory_ceiling_known},
           {"source", s.source},
           {"origin", std::string(to_string(s.origin))}});
      ss.push_back(j);
    }
    out << nlohmann::json{{"format", "benchscope-roofline"},
                          {"version", 1},
                          {"ops_note",
                           "stage ops are integer arithmetic ops (add, sub, mul, shift) per the source; "
                           "bytes are compulsory DRAM traffic with perfect cache reuse, no write-allocate"},
                          {"ceilings", cs},
                          {"rotation", rs},
                          {"stages", ss},
                          {"skipped_stages", stages.skipped}}
               .dump(2)
        << '\n';
    return 0;
  }

  TextTable ct({"platform", "device", "compute ceiling", "memory ceiling", "ridge (FLOP/B)"});
  for (const RooflineCeiling& c : ceilings) {
    const auto ridge = c.ridge_intensity();
    ct.add({c.platform, c.device, format_si(c.peak_flops, "FLOPS") + " (" + c.peak_source + ")",
            c.bandwidth_bps ? format_si(*c.bandwidth_bps, "B/s") : "not measured",
            ridge ? format_number("%.2f", *ridge) : "\xE2\x80\x93"});
  }
  out << "Ceilings\n";
  ct.print(out);
  out << "\nRotation kernel at its peak (6 D N flops per worker over 16 D + 4 bytes)\n";
  TextTable rt({"run", "intensity (FLOP/B)", "achieved", "of roof"});
  for (const auto& [row, p] : rotation)
    rt.add({row.platform + ": " + p.label, format_number("%.4g", p.intensity), format_si(p.flops, "FLOPS"),
            format_number("%.0f %%", 100 * p.fraction)});
  rt.print(out);
  out << "\nPreprocessing stages (demosaic + reprojection) from the pipeline runs\n";
  if (stages.placed.empty()) {
    out << "  none: no pipeline run with a preprocessing stage matches a device with a ceiling\n";
  } else {
    TextTable st({"platform / device", "kernels", "ops/px", "B/px", "intensity (op/B)", "time (ms)", "achieved",
                  "of roof", "bound"});
    for (const StagePlacement& s : stages.placed)
      st.add({s.platform + " / " + s.device, s.cost.label, format_number("%.1f", s.cost.ops_per_output_pixel),
              format_number("%.1f", s.cost.bytes_per_output_pixel), format_number("%.3f", s.point.intensity),
              format_number("%.2f", s.time.mean_s * 1e3) + " \xC2\xB1 " + format_number("%.2f", s.time.sd_s * 1e3) +
                  " (n = " + std::to_string(s.time.n) + ")",
              format_si(s.point.flops, "op/s"), format_number("%.1f %%", 100 * s.point.fraction),
              !s.memory_ceiling_known ? "? (no bandwidth)"
              : s.point.memory_bound  ? "memory"
                                      : "compute"});
    st.print(out);
    out << "  ops: integer adds, multiplies and shifts of the kernels as implemented (clamps, loads, addressing not\n"
           "  counted); bytes: compulsory DRAM traffic (each mosaic/RGB/LUT byte read once, output written once, no\n"
           "  write-allocate); output view taken as the camera frame's size (not stored in pipeline runs).\n";
  }
  for (const std::string& s : stages.skipped) out << "  not placed: " << s << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "roofline",
    "roofline per device: ceilings, the rotation kernel and the preprocessing stages placed on them",
    "usage: benchscope-cli roofline (WORKSPACE | PATH...) [--json]\n"
    "  Per device: the compute ceiling (theoretical peak, else the measured peak) and the memory ceiling (best\n"
    "  STREAM triad from `run bandwidth`, or clpeak). Placed on them: the rotation kernel's runs at their peak,\n"
    "  and each pipeline run's preprocessing stage (demosaic + reprojection, or the fused kernel) at its modelled\n"
    "  arithmetic intensity (integer ops and compulsory DRAM bytes per pixel, counted in BenchScope's kernels)\n"
    "  and its measured throughput (ops per frame / mean stage time), under the ceiling of the device that ran it.\n"
    "  --json prints the same as one document (format benchscope-roofline).",
    out_only<run_roofline>,
});

}  // namespace
}  // namespace bs::cli
