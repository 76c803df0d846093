// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/platform_comparison.h"

#include "analysis/stats/units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/platform/platform_battery.h"
#include "analysis/power/battery.h"
#include "analysis/power/power.h"
#include "analysis/power/power_stats.h"
#include "analysis/stats/measurement_text.h"

namespace bs {
namespace {

std::string peak_how(const PeakRow& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "peak of %s / %s / %s, D = %d, at %lld workers (n = %zu)", r.device.c_str(),
                r.backend.c_str(), r.variant.c_str(), r.dims, static_cast<long long>(r.peak.workers), r.peak.at_peak.n);
  return buf;
}

PlatformRow& row_for(std::vector<PlatformRow>& rows, const std::string& platform) {
  for (auto& r : rows)
    if (r.platform == platform) return r;
  rows.push_back({});
  rows.back().platform = platform;
  return rows.back();
}

void add_power(PlatformRow& row, const PowerTrace& trace, const ComparisonOptions& o) {
  const PowerStats s = power_stats(trace, {.supply_v = o.supply_v});
  if (!s.power_w) return;
  row.mean_power_w = s.power_w->summary.mean;
  row.max_power_w = s.power_w->summary.max;
  std::string how = "mean and max power of " + trace.label + " (n = " + std::to_string(s.n) + ")";
  if (s.supply_v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, ", current x %.2f V", *s.supply_v);
    how += buf;
  }
  row.sources[column::kPower] = {trace.provenance.source_file, trace.provenance.origin, how};
  row.power_log = trace.label;
  row.power_measurement = measurement_text(trace.provenance);
  if (auto f = check_power_trace_bundled(trace); !f.empty()) row.flags[column::kPower] = std::move(f);
  const double peak = row.best_peak_flops();
  if (peak > 0) {
    row.gflops_per_watt_mean = peak / 1e9 / s.power_w->summary.mean;
    if (s.current_a && s.supply_v)
      row.gflops_per_watt_paper = paper_flops_per_watt(peak, *s.supply_v, s.current_a->summary.max) / 1e9;
  }
}

// Spreads the peaks' and the power log's flags (set above) over every cell computed from them.
void attach_flags(PlatformRow& row) {
  const std::vector<PlausibilityFlag> power =
      row.flags.count(column::kPower) ? row.flags[column::kPower] : std::vector<PlausibilityFlag>{};
  if (row.gpu && !row.gpu->flags.empty()) row.flags[column::kGpuPeak] = row.gpu->flags;
  if (row.cpu && !row.cpu->flags.empty()) row.flags[column::kCpuPeak] = row.cpu->flags;
  std::vector<PlausibilityFlag> per_watt = row.best_peak() ? row.best_peak()->flags : std::vector<PlausibilityFlag>{};
  merge_flags(per_watt, power);
  if (!per_watt.empty() && (row.gflops_per_watt_paper || row.gflops_per_watt_mean)) {
    row.flags["gflops_w_paper"] = per_watt;
    row.flags["gflops_w_mean"] = per_watt;
  }
  if (power.empty()) return;
  row.flags["max_power"] = power;
  for (const char* c : {column::kEnergyPerFrame, column::kEnergyPerStage, column::kBattery, column::kFramesPerWh})
    row.flags[c] = power;
}

}  // namespace

const PeakRow* PlatformRow::best_peak() const {
  if (gpu && (!cpu || gpu->peak.flops >= cpu->peak.flops)) return &*gpu;
  return cpu ? &*cpu : nullptr;
}

std::vector<PlausibilityFlag> PlatformRow::all_flags() const {
  std::vector<PlausibilityFlag> out;
  for (const auto& [column, f] : flags) merge_flags(out, f);
  return out;
}

double PlatformRow::best_peak_flops() const {
  return std::max(gpu ? gpu->peak.flops : 0.0, cpu ? cpu->peak.flops : 0.0);
}

namespace {
// A flagged peak counts at most the device's spec or computed peak; 0 when neither is known.
double trusted_flops(const std::optional<PeakRow>& p) {
  if (!p) return 0;
  if (p->flags.empty()) return p->peak.flops;
  double cap = -1;
  if (p->spec && p->spec->fp32_peak_flops > 0) cap = p->spec->fp32_peak_flops;
  if (p->fraction_of_theoretical && *p->fraction_of_theoretical > 0) {
    const double theoretical = p->peak.flops / *p->fraction_of_theoretical;
    cap = cap < 0 ? theoretical : std::min(cap, theoretical);
  }
  return cap < 0 ? 0 : std::min(p->peak.flops, cap);
}
}  // namespace

double PlatformRow::trusted_peak_flops() const { return std::max(trusted_flops(gpu), trusted_flops(cpu)); }

std::optional<double> energy_per_frame_j(const PowerTrace& trace, double from_s, double to_s, std::size_t frames,
                                         std::optional<double> supply_v) {
  if (frames == 0 || !(to_s > from_s) || trace.time_s.empty()) return std::nullopt;
  const double t0 = trace.time_s.front();
  if (from_s < 0 || t0 + to_s > trace.time_s.back() + 1e-9) return std::nullopt;
  const PowerStats s = power_stats(trace, {.supply_v = supply_v, .from_s = from_s, .to_s = to_s});
  if (!s.energy_j) return std::nullopt;
  return *s.energy_j / static_cast<double>(frames);
}

namespace {

Summary stage_ms(const StageStats& s) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {s.n, s.mean_s * 1e3, s.sd_s * 1e3, s.min_s ? *s.min_s * 1e3 : nan, s.max_s ? *s.max_s * 1e3 : nan};
}

}  // namespace

std::optional<PipelineTimings> pipeline_timings(const PipelineRun& run) {
  const StageStats* pre = run.stage(pipeline_stage::kPreprocess);
  if (!pre) return std::nullopt;
  PipelineTimings t;
  t.platform = run.platform;
  t.preprocess_ms = stage_ms(*pre);
  if (const StageStats* det = run.stage(pipeline_stage::kDetect)) t.detect_ms = stage_ms(*det);
  t.frames = pre->n;
  t.source = {run.provenance.source_file, run.provenance.origin,
              run.device + " (" + run.backend + "), " + std::to_string(pre->n) + " frames" +
                  (run.provenance.note.empty() ? std::string() : "; " + run.provenance.note)};
  return t;
}

std::vector<PipelineTimings> pipeline_timings(std::span<const PipelineRun> runs) {
  std::vector<PipelineTimings> out;
  for (const PipelineRun& r : runs) {
    auto t = pipeline_timings(r);
    if (!t) continue;
    const auto same =
        std::find_if(out.begin(), out.end(), [&](const PipelineTimings& p) { return p.platform == t->platform; });
    if (same != out.end())
      *same = std::move(*t);
    else
      out.push_back(std::move(*t));
  }
  return out;
}

std::vector<PlatformRow> compare_platforms(std::span<const FlopsRun> runs, std::span<const PowerTrace> traces,
                                           std::span<const PipelineTimings> pipelines, const ComparisonOptions& o) {
  std::vector<PlatformRow> rows;
  for (const PeakRow& p : peak_table(runs)) {
    PlatformRow& row = row_for(rows, p.platform);
    auto& slot = p.device_kind == DeviceKind::Cpu ? row.cpu : row.gpu;
    if (slot && slot->peak.flops >= p.peak.flops) continue;
    slot = p;
    row.sources[p.device_kind == DeviceKind::Cpu ? column::kCpuPeak : column::kGpuPeak] = {p.source_file, p.origin,
                                                                                           peak_how(p)};
  }
  for (const PowerTrace& t : traces) {
    PlatformRow& row = row_for(rows, t.platform);
    ++row.power_logs;
    if (!row.mean_power_w) add_power(row, t, o);  // the first trace of a platform
  }
  for (const PipelineTimings& p : pipelines) {
    PlatformRow& row = row_for(rows, p.platform);
    row.preprocess_ms = p.preprocess_ms;
    row.detect_ms = p.detect_ms;
    row.sources[column::kPipeline] = p.source;
    const double frame_ms = p.preprocess_ms.mean + (p.detect_ms ? p.detect_ms->mean : 0.0);
    if (frame_ms > 0) row.fps = 1000.0 / frame_ms;
    // Energy per frame: from the power trace over the pipeline's window when both are known, otherwise the mean
    // power of the platform's log times the frame time (labelled as such).
    const auto trace =
        std::find_if(traces.begin(), traces.end(), [&](const PowerTrace& t) { return t.platform == p.platform; });
    if (trace != traces.end() && p.window_from_s && p.window_to_s) {
      row.energy_per_frame_j = energy_per_frame_j(*trace, *p.window_from_s, *p.window_to_s, p.frames, o.supply_v);
      if (row.energy_per_frame_j)
        row.sources[column::kEnergyPerFrame] = {
            trace->provenance.source_file, trace->provenance.origin,
            "energy of " + trace->label + " over the pipeline run / " + std::to_string(p.frames) + " frames"};
    }
    // Per stage: the platform's mean power over each stage's mean time (the paper's NUC: 40.52 W x 6.21 ms).
    if (row.mean_power_w) {
      row.energy_per_preprocess_j = *row.mean_power_w * p.preprocess_ms.mean / 1000.0;
      if (p.detect_ms) row.energy_per_inference_j = *row.mean_power_w * p.detect_ms->mean / 1000.0;
      row.sources[column::kEnergyPerStage] = {p.source.source_file, p.source.origin,
                                              "mean power of the platform's log x the stage's mean time"};
    }
    if (!row.energy_per_frame_j && row.mean_power_w && frame_ms > 0) {
      row.energy_per_frame_j = *row.mean_power_w * frame_ms / 1000.0;
      row.sources[column::kEnergyPerFrame] = {p.source.source_file, p.source.origin,
                                              "mean power of the platform's log x mean frame time (not time-aligned)"};
    }
  }
  if (!o.mission.empty()) parse_mission(o.mission);  // a bad mission is an error even without power logs
  for (PlatformRow& row : rows) {
    if (!row.mean_power_w) continue;
    char how[320];
    if (o.mission.empty()) {
      const double load = *row.mean_power_w + o.extra_load_w;
      row.battery_load_w = load;
      row.battery_runtime_h =
          constant_power_runtime_h(o.battery_nominal_v, o.battery_capacity_ah, load, o.usable_fraction);
      std::snprintf(how, sizeof how, "constant power: %.2f V x %.3f Ah x %.0f %% / (%.2f W computer + %.2f W parallel)",
                    o.battery_nominal_v, o.battery_capacity_ah, o.usable_fraction * 100, *row.mean_power_w,
                    o.extra_load_w);
    } else {
      // The mission's phases with the computer and the parallel load on top, through the same simulation as the
      // Battery tab; the pack is only its nominal energy in the constant-power model.
      const Mission m = platform_mission(*row.mean_power_w, o.extra_load_w, o.mission);
      BatteryPack pack;
      pack.cells_series = 1;
      pack.nominal_cell_v = o.battery_nominal_v;
      pack.capacity_ah = o.battery_capacity_ah;
      DischargeOptions d;
      d.depth_of_discharge = o.usable_fraction;
      const DischargeResult r = simulate_discharge(pack, m, d);
      row.battery_load_w = m.mean_load_w();
      row.battery_runtime_h = r.runtime_s / 3600.0;
      std::snprintf(how, sizeof how,
                    "mission %s repeated, %.2f W computer + %.2f W parallel in every phase (mean load %.2f W), "
                    "constant power on %.2f V x %.3f Ah x %.0f %%: %s",
                    o.mission.c_str(), *row.mean_power_w, o.extra_load_w, m.mean_load_w(), o.battery_nominal_v,
                    o.battery_capacity_ah, o.usable_fraction * 100, r.stop_reason.c_str());
    }
    row.sources[column::kBattery] = {
        row.sources.count(column::kPower) ? row.sources[column::kPower].source_file : "",
        row.sources.count(column::kPower) ? row.sources[column::kPower].origin : DataOrigin::Unknown, how};
    if (row.energy_per_frame_j && *row.energy_per_frame_j > 0) {
      row.frames_per_wh = 3600.0 / *row.energy_per_frame_j;
      const CellSource& e = row.sources[column::kEnergyPerFrame];
      row.sources[column::kFramesPerWh] = {e.source_file, e.origin,
                                           "frames preprocessed and detected per Wh of the computer: 3600 / energy "
                                           "per frame (" +
                                               e.how + ")"};
    }
  }
  for (PlatformRow& row : rows) attach_flags(row);
  return rows;
}

std::vector<PlatformVerdict> recommend(std::span<const PlatformRow> rows, const Constraints& c) {
  std::vector<PlatformVerdict> out;
  for (const PlatformRow& row : rows) {
    PlatformVerdict v;
    v.platform = row.platform;
    const auto check = [&](const char* name, const char* unit, double required, std::optional<double> actual,
                           bool at_most) {
      ConstraintCheck k{name, unit, required, actual, false, 0};
      if (actual) {
        k.margin = at_most ? required - *actual : *actual - required;
        k.met = k.margin >= 0;
      }
      v.checks.push_back(k);
    };
    if (c.power_budget_w) check("power budget (mean power)", "W", *c.power_budget_w, row.mean_power_w, true);
    if (c.min_fps) check("frame rate (preprocessing + detection)", "fps", *c.min_fps, row.fps, false);
    // In minutes, the unit the user sets the constraint in (GUI and --min-runtime): a margin of "-0.12 h" reads badly.
    if (c.min_runtime_h)
      check("battery runtime", "min", *c.min_runtime_h * 60,
            row.battery_runtime_h ? std::optional<double>(*row.battery_runtime_h * 60) : std::nullopt, false);
    v.meets_all = std::all_of(v.checks.begin(), v.checks.end(), [](const ConstraintCheck& k) { return k.met; });
    if (!row.mean_power_w)
      v.note = "no power log: its power and battery runtime are unknown";
    else if (row.best_peak_flops() <= 0)
      v.note = "no FLOPS runs";
    out.push_back(std::move(v));
  }
  // Among the platforms that meet every constraint, the most compute wins (the paper's reasoning). The flagged figure
  // stays in the tables and charts, marked; the ranking uses the most the device can plausibly deliver instead and says
  // so (a demanding reader must see which number decided, and that it was not measured).
  for (std::size_t i = 0; i < rows.size(); ++i) {
    out[i].ranked_flops = rows[i].trusted_peak_flops();
    const PeakRow* peak = rows[i].best_peak();
    if (peak && !peak->flags.empty())
      out[i].ranking_note = "ranked at " + format_si(out[i].ranked_flops, "FLOPS") +
                            ", not at its flagged best peak of " + format_si(peak->peak.flops, "FLOPS") + " (" +
                            peak->device +
                            "): a flagged peak counts at most its device's spec or computed peak, and not at all "
                            "without one";
  }
  const PlatformRow* best = nullptr;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (out[i].meets_all && out[i].note.empty() &&
        (!best || out[i].ranked_flops > out[static_cast<std::size_t>(best - rows.data())].ranked_flops))
      best = &rows[i];
  for (std::size_t i = 0; i < rows.size(); ++i) out[i].recommended = best == &rows[i];
  return out;
}

std::string unmet_text(const ConstraintCheck& k) {
  // A check without a value whose name already says why ("control loop: load not applied: ...") stands as it is.
  if (!k.actual) return k.name.find(':') != std::string::npos ? k.name : k.name + ": no data";
  char b[96];
  std::snprintf(b, sizeof b, " %.2f %s (%.2f %s %s)", *k.actual, k.unit.c_str(), std::abs(k.margin), k.unit.c_str(),
                is_ceiling(k) ? "over" : "short");
  return k.name.substr(0, k.name.find(" (")) + b;
}

void add_requirement_checks(std::vector<PlatformVerdict>& verdicts,
                            const std::function<std::vector<ConstraintCheck>(const std::string&)>& checks_of) {
  for (PlatformVerdict& v : verdicts) {
    for (ConstraintCheck& k : checks_of(v.platform)) v.checks.push_back(std::move(k));
    v.meets_all = std::all_of(v.checks.begin(), v.checks.end(), [](const ConstraintCheck& k) { return k.met; });
  }
  PlatformVerdict* best = nullptr;
  for (PlatformVerdict& v : verdicts)
    if (v.meets_all && v.note.empty() && (!best || v.ranked_flops > best->ranked_flops)) best = &v;
  for (PlatformVerdict& v : verdicts) v.recommended = &v == best;
}

double tightest_relative_margin(std::span<const ConstraintCheck> checks) {
  double m = INFINITY;
  for (const ConstraintCheck& k : checks)
    if (k.actual) m = std::min(m, k.required > 0 ? k.margin / k.required : (k.margin >= 0 ? 0.0 : -INFINITY));
  return m;
}

}  // namespace bs
