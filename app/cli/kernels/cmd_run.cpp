// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli run flops: measure the paper's kernel on this machine and write run JSON v1.
#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>

#include "analysis/peaks/ceiling_check.h"
#include "analysis/peaks/flops.h"
#include "analysis/power/sweep_energy.h"
#include "analysis/stats/stats.h"
#include "analysis/stats/units.h"
#include "commands/run_flops_grammar.h"
#include "common/args.h"
#include "common/command.h"
#include "common/events_option.h"
#include "common/signals.h"
#include "kernels/ceilings/ceiling_cache.h"
#include "kernels/cpu_args.h"
#include "kernels/flops_home.h"
#include "kernels/sweep.h"
#include "kernels/worker_spec.h"
#include "power/power_args.h"
#include "runs/run_json.h"
#include "sensors/recording_csv.h"
#include "store/home_batch.h"
#include "store/workspace.h"

namespace bs::cli {

int run_bandwidth(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err);  // cmd_run_bandwidth.cpp

namespace {

// Energy of each sweep point from the phases the sweep marked: J per timed run (the point's energy over its
// repeats) and GFLOPS/W at the point's mean power.
void print_point_energies(std::ostream& out, const PowerTrace& trace, const std::vector<FlopsRun>& runs) {
  print_phase_energies(out, trace);
  out << "energy per sweep point (" << to_string(trace.provenance.measurement) << ": " << trace.provenance.sensor
      << "):\n";
  char line[256];
  // The columns and digits of the Kernel Runner's energy table.
  std::snprintf(line, sizeof line, "  %6s %10s %12s %12s %12s %12s %10s %s\n", "D", "W", "GFLOPS", "mean W",
                "J (point)", "J per run", "GFLOPS/W", "n samples");
  out << line;
  for (const PointEnergy& p : sweep_point_energies(trace, runs)) {
    std::snprintf(line, sizeof line, "  %6d %10lld %12.3f %12.4f %12.4f %12.4f %10.3f %zu%s\n", p.dims,
                  static_cast<long long>(p.workers), p.gflops, p.mean_power_w, p.energy_j, p.joules_per_run,
                  p.gflops_per_watt, p.samples, short_point_mark(p.samples).c_str());
    out << line;
  }
}

// "  = X % of the empirical ceiling ..." for a CPU SIMD or OpenCL/CUDA device figure, with flags spelled out; a hint
// when none is cached.
void print_ceiling_comparison(double flops, const kernels::Backend& backend, const kernels::CpuInfo& cpu,
                              std::ostream& out) {
  const bool device = backend.id != "cpu-simd";
  const auto cached = device ? kernels::cached_device_ceilings(backend) : kernels::cached_ceilings(cpu);
  std::optional<double> ceiling;
  std::string how = device ? "no empirical ceiling cached for this device (bench kernels or devices --measure-ceilings)"
                           : "no empirical ceiling cached for this CPU and ISA (bench kernels or devices "
                             "--measure-ceilings)";
  if (cached && cached->rotation_mix.measured()) {
    ceiling = summarize(cached->rotation_mix.values).mean;
    how = "rotation mix, cached, measured " + cached->date;
  }
  const auto cmp =
      compare_to_ceilings(flops, device ? backend.theoretical_peak_flops : cpu.peak_flops, ceiling, "the peak", how);
  out << "  " << fraction_text(cmp.fraction_of_peak, !cmp.flags.empty()) << " of the computed peak, "
      << fraction_text(cmp.fraction_of_ceiling, !cmp.flags.empty()) << " of the empirical ceiling ("
      << (ceiling ? format_si(*ceiling, "FLOPS") + ", " : "") << how << ")\n";
  for (const PlausibilityFlag& f : cmp.flags) out << "  \xE2\x9A\xA0 " << f.code << ": " << f.reason << '\n';
}

// The result event of a sweep: each D's peak and where the runs were written.
nlohmann::json result_fields(const std::vector<FlopsRun>& runs, const commands::RunFlopsSettings& settings) {
  nlohmann::json peaks = nlohmann::json::array();
  std::size_t points = 0;
  for (const FlopsRun& r : runs) points += r.samples.size();
  for (const PeakRow& row : peak_table(runs))
    peaks.push_back({{"backend", row.backend},
                     {"variant", row.variant},
                     {"dims", row.dims},
                     {"peak_flops", row.peak.flops},
                     {"sd_flops", row.peak.at_peak.sd},
                     {"n", row.peak.at_peak.n},
                     {"workers_at_peak", row.peak.workers}});
  return {{"runs", runs.size()},
          {"points", points},
          {"peaks", peaks},
          {"out", settings.out ? nlohmann::json(*settings.out) : nlohmann::json(nullptr)},
          {"workspace", settings.workspace ? nlohmann::json(*settings.workspace) : nlohmann::json(nullptr)}};
}

int run_flops_with(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err,
                   remote::EventWriter* events) {
  if (raw.empty() || raw[0] != "flops") throw UsageError("expected 'run flops'");
  const commands::RunFlopsSettings settings = commands::run_flops_from_words({raw.begin() + 1, raw.end()});
  kernels::SweepSpec spec;
  spec.workers = kernels::parse_worker_spec(settings.workers);  // checked by the grammar
  spec.dims = kernels::parse_dims_list(settings.points);
  spec.iterations = settings.iterations;
  spec.repeats = settings.repeats;
  spec.warmup = settings.warmup;
  spec.variant = settings.variant == "paper" ? kernels::Variant::Paper : kernels::Variant::Throughput;

  kernels::CpuInfo cpu = cpu_from_isa(settings.isa);
  const auto backends = kernels::available_backends(cpu);
  std::string backend_id = settings.backend;
  if (const auto& device = settings.device) backend_id += ":" + *device;  // --backend opencl --device 1
  const kernels::Backend* found = nullptr;
  try {
    found = &kernels::find_backend(backends, backend_id);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const kernels::Backend& backend = *found;
  if (!settings.quiet)
    err << "benchscope-cli: " << backend.label << " on " << backend.device_name << " (" << backend.details
        << "), theoretical peak " << format_si(backend.theoretical_peak_flops, "FLOPS") << '\n';
  // With --events the text goes to stderr; progress is an event, not a line redrawn in place.
  const bool quiet = settings.quiet;
  std::ostream& text = events ? err : out;
  if (events)
    events->write("sweep", {{"backend", backend.label},
                            {"backend_id", backend.id},
                            {"device", backend.device_name},
                            {"theoretical_peak_flops", backend.theoretical_peak_flops},
                            {"workers", spec.workers},
                            {"dims", spec.dims},
                            {"iterations", spec.iterations},
                            {"repeats", spec.repeats}});
  const CancelToken& cancel = interrupt_token();
  // The sampler runs on its own thread; the sweep marks its phases: the warm-up of each D (the time from the
  // previous point's end to this D's first point) and each point.
  const auto power = start_power(settings.power, err, quiet, events);
  // Each point lasts long enough for kMinSamplesPerPoint sensor samples (the Kernel Runner does the same).
  if (power) spec.min_point_s = min_point_seconds(power->interval_s());
  double last_end = power ? power->now_s() : 0;
  int current_d = -1;
  kernels::SweepResult result;
  try {
    result = kernels::run_sweep(
        backend, cpu, spec, cancel,
        [&](double f, std::string_view step) {
          if (events)
            events->progress(f, step);
          else if (!quiet)
            err << "\r" << std::setw(5) << std::fixed << std::setprecision(1) << f * 100 << " % " << step
                << "          " << std::flush;
          if (!power || !step.starts_with("W=")) return;
          const auto comma = step.find(", D=");
          if (comma == std::string_view::npos) return;
          const std::string w(step.substr(2, comma - 2)), d(step.substr(comma + 4));
          if (std::stoi(d) != current_d) {
            current_d = std::stoi(d);
            if (spec.warmup) power->add_phase(sweep_warmup_phase(current_d), last_end, power->now_s());
          }
          power->begin_phase(sweep_point_phase(std::stoll(w), current_d));
        },
        [&](const FlopsRun& run) {
          if (events) events->write("point", remote::point_fields(run));
          if (!power) return;
          power->end_phase();
          last_end = power->now_s();
        });
  } catch (const std::invalid_argument& e) {  // sizes or D the backend refuses before running anything
    throw UsageError(e.what());
  }
  if (!quiet && !events) err << '\n';
  if (result.cancelled) err << "benchscope-cli: cancelled; keeping the " << result.runs.size() << " partial run(s)\n";

  std::optional<PowerTrace> trace;
  if (power) {
    // Named after the run, so the workspace shows which run it belongs to.
    const FlopsRun* first = result.runs.empty() ? nullptr : &result.runs.front();
    trace = power->finish("run flops " + backend.label + (first ? " " + first->variant : std::string()) + " " +
                          (first ? first->provenance.date : std::string()));
    if (first) trace->platform = first->platform;
  }
  if (result.runs.empty()) {
    err << "benchscope-cli: error: no point completed; nothing written\n";
    if (events) events->error("no point completed; nothing written");
    return 1;
  }
  if (const auto& path = settings.out) {
    save_run_json(*path, result.runs);
    if (!quiet) err << "benchscope-cli: wrote " << *path << '\n';
    if (trace) {
      sensors::save_recording_csv(power_csv_beside(*path), *trace);
      if (!quiet) err << "benchscope-cli: wrote " << power_csv_beside(*path) << '\n';
    }
  }
  if (const auto& ws_path = settings.workspace) {
    bring_home(*ws_path, flops_home(result.runs, trace, "benchscope-cli run flops"));  // the trace in the same import
    if (!quiet) err << "benchscope-cli: stored " << result.runs.size() << " run(s) in " << *ws_path << '\n';
  }
  if (events) events->write("result", result_fields(result.runs, settings));
  if (settings.json) {
    text << write_run_json(result.runs);
  } else {
    for (const PeakRow& row : peak_table(result.runs)) {
      text << row.backend << ", D = " << row.dims << ": peak " << format_si(row.peak.flops, "FLOPS") << " \xC2\xB1 "
           << format_si(row.peak.at_peak.sd, "FLOPS") << " (n = " << row.peak.at_peak.n
           << ") at W = " << row.peak.workers;
      if (row.fraction_of_theoretical)
        text << ", " << std::setprecision(1) << std::fixed << *row.fraction_of_theoretical * 100 << " % of "
             << format_si(*row.theoretical_flops, "FLOPS") << " theoretical";
      text << " [variant " << row.variant << "]\n";
      // The empirical ceiling of this CPU and ISA, or of the OpenCL/CUDA device, from the per-host cache.
      if (found->id == "cpu-simd" || found->ceiling_kernels)
        print_ceiling_comparison(row.peak.flops, *found, cpu, text);
    }
    if (trace) print_point_energies(text, *trace, result.runs);
  }
  return result.cancelled ? 1 : 0;
}

int run_flops(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  if (!raw.empty() && raw[0] == "bandwidth") return run_bandwidth(raw, out, err);
  return run_with_events("run flops", raw, out,
                         [&](remote::EventWriter* events) { return run_flops_with(raw, out, err, events); });
}

const CommandRegistrar registrar({
    "run",
    "measure the paper's rotation kernel (FLOPS sweep) or memory bandwidth on this machine",
    "usage: benchscope-cli run flops [--backend cpu|cpu-simd|cpu-scalar|opencl|cuda [--device N]]\n"
    "         [--variant throughput|paper] [--isa avx512|avx2|sse4|generic]\n"
    "         [--points 1,2,4] [--iterations N] [--workers SPEC] [--repeats R] [--no-warmup]\n"
    "         [--out run.json] [--workspace W.bsw] [--json] [--quiet]\n"
    "  SPEC: 256:1024000:256 (start:stop:step), 1,2,4,8, or mixes such as 1,2,4:64:4.\n"
    "  paper: the paper's kernel (OpenMP task / work-item / thread per worker; OpenCL and CUDA: float, float2,\n"
    "  float4 for D = 1, 2, 4). throughput: enough independent vector chains per thread to reach the FMA pipes'\n"
    "  peak (CPU: all W*D points packed into vectors; OpenCL: float16x4; CUDA: float4x4).\n"
    "  Every output is checked against the closed form D*(cos 2N + sin 2N). Ctrl+C keeps the completed points.\n"
    "  --isa forces the CPU SIMD dispatch to one instruction set this CPU has. CPU SIMD peaks are also shown as\n"
    "  % of the empirical ceiling cached for this CPU and ISA (flagged above the computed peak or the ceiling).\n"
    "         [--power SENSOR|auto|none] [--power-interval-ms 100] [--sysfs-root DIR]\n"
    "  --power records the on-board sensors during the sweep (benchscope-cli sensors lists them): phases for the\n"
    "  warm-up and every point, energy per point (J per timed run) and GFLOPS/W at the point's mean power; the\n"
    "  trace is stored with the run (--workspace) and written beside it as RUN.power.csv (--out RUN.json).\n"
    "         [--events jsonl]\n"
    "  --events jsonl: the event stream on stdout (progress, each point, power readings, the result; one JSON\n"
    "  object per line, docs/remote-events-v1.md) and the text on stderr.\n"
    "usage: benchscope-cli run bandwidth [--backend cpu|cpu-scalar|opencl [--device N]] [--mib 128]\n"
    "         [--repeats 10] [--workspace W.bsw] [--json] [--quiet]\n"
    "  STREAM triad a = b + q c over three float arrays of --mib MiB (12 bytes per element), mean ± SD of the\n"
    "  repetitions in GB/s: the memory ceiling of the roofline. --workspace stores it as a result set.",
    run_flops,
});

}  // namespace
}  // namespace bs::cli
