// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli bench kernels: figures and ratios measured in one process (a benchmark, not a test).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <thread>

#include "analysis/peaks/flops.h"
#include "analysis/power/decimate.h"
#include "analysis/power/phase_energy.h"
#include "analysis/power/power.h"
#include "analysis/stats/stats.h"
#include "commands/bench_kernels_grammar.h"
#include "common/args.h"
#include "common/bench_host.h"
#include "common/command.h"
#include "common/signals.h"
#include "common/subcommand.h"
#include "headroom/bench_headroom.h"
#include "kernels/bench_ceilings.h"
#include "kernels/bench_range_stats.h"
#include "kernels/ceilings/ceiling_cache.h"
#include "kernels/cpu_args.h"
#include "kernels/sweep.h"
#include "power/power_args.h"
#include "sustain/bench_sustain_sampler.h"
#include "vision/bench_dnn.h"
#include "vision/bench_pipeline.h"
#include "vision/bench_tuner.h"
#include "vision/bench_vision.h"

namespace bs::cli {

int bench_power_csv(const std::vector<std::string>& args, std::ostream& out);  // in cmd_power.cpp

namespace {

// Per-core peak of a backend that runs on this CPU's cores (CPU SIMD, CPU scalar, an OpenCL CPU device); 0 for
// GPUs, where the host's CPU time says nothing about the device.
double per_core_peak(const kernels::Backend& b, const kernels::CpuInfo& cpu) {
  if (b.kind != DeviceKind::Cpu) return 0;
  if (b.id == "cpu-scalar") return b.theoretical_peak_flops;  // one thread
  return cpu.peak_flops / cpu.threads;
}

// What sampling the power sensors costs the kernel: the CPU SIMD throughput point R times without the sampler,
// R times with it running (its phases give the energy per run), R times without again; medians and their ratio.
void bench_power_overhead(const commands::BenchKernelsSettings& settings, const kernels::Backend& b,
                          const kernels::CpuInfo& cpu, int runs, std::ostream& out) {
  const kernels::RotationParams params{4, 40000};
  const std::int64_t workers = settings.workers.value_or(16384);
  const double flops = rotation_flop_count(params.dims, params.iterations, workers);
  std::vector<float> outputs;
  std::vector<double> without, with;
  const auto timed = [&](std::vector<double>& into) {
    into.push_back(flops / b.run_point(params, workers, kernels::Variant::Throughput, outputs, interrupt_token()) /
                   1e9);
  };
  b.run_point(params, workers, kernels::Variant::Throughput, outputs, interrupt_token());  // warm-up
  for (int r = 0; r < runs; ++r) timed(without);
  std::ostringstream chosen;
  auto rec = start_power(settings.power, chosen, false);
  for (int r = 0; r < runs; ++r) {
    rec->begin_phase("run " + std::to_string(r + 1));
    timed(with);
    rec->end_phase();
  }
  const PowerTrace trace = rec->finish("bench kernels");
  for (int r = 0; r < runs; ++r) timed(without);
  (void)cpu;
  const double a = median(without), p = median(with);
  char line[400];
  std::snprintf(line, sizeof line,
                "\npower sampling overhead (%s, W = %lld, %d runs with the sampler between 2 x %d without):\n"
                "  without: %.2f GFLOPS (median), with: %.2f GFLOPS; with / without = %.4f (%.2f %% cost)\n",
                b.label.c_str(), static_cast<long long>(workers), runs, runs, a, p, p / a, 100.0 * (1.0 - p / a));
  out << line << "  " << chosen.str();
  // The direct measure: what the sampling thread itself used, independent of how noisy the ratio above is.
  if (std::isfinite(rec->sampler_cpu_s()) && rec->recorded_s() > 0) {
    const double share = rec->sampler_cpu_s() / rec->recorded_s();
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::snprintf(line, sizeof line,
                  "  sampler thread: %.3f ms CPU in %.3f s of recording, %zu samples = %.4f %% of one core, %.4f %% "
                  "of this machine's %u hardware threads\n",
                  rec->sampler_cpu_s() * 1e3, rec->recorded_s(), trace.time_s.size(), 100.0 * share,
                  100.0 * share / threads, threads);
    out << line;
  }
  const auto energies = phase_energies(trace);
  double joules = 0, watts = 0;
  for (const PhaseEnergy& e : energies) joules += e.energy_j, watts += e.mean_power_w;
  if (!energies.empty()) {
    const double n = static_cast<double>(energies.size());
    // A sensor that read no energy (a counter that did not move) gives no GFLOPS/W, never "inf".
    char per_watt[48] = "no GFLOPS/W (no power read)";
    if (watts > 0) std::snprintf(per_watt, sizeof per_watt, "%.3f GFLOPS/W at mean power", p / (watts / n));
    std::snprintf(line, sizeof line, "  %s: %.3f J per run, mean %.2f W, %s (%s)\n",
                  std::string(to_string(trace.provenance.measurement)).c_str(), joules / n, watts / n, per_watt,
                  trace.provenance.sensor.c_str());
    out << line;
  }
}

// The empirical ceilings of every device backend (OpenCL, CUDA), `runs` repetitions each, printed and cached; a
// device whose micro-kernel gives a wrong result fails the command (std::runtime_error).
std::map<std::string, kernels::CeilingSet> measure_device_ceilings(const std::vector<kernels::Backend>& backends,
                                                                   int runs, std::ostream& out) {
  std::map<std::string, kernels::CeilingSet> sets;
  kernels::CeilingSpec spec;
  spec.repeats = runs;
  for (const kernels::Backend& b : backends) {
    if (!b.ceiling_kernels) continue;
    kernels::CeilingSet set = kernels::measure_device_ceilings(b, spec, interrupt_token());
    out << "empirical ceilings of " << b.id << " " << b.device_name << " (" << b.label << "), measured now, " << runs
        << " repetitions, timed on the device:\n";
    print_ceilings(set, out);
    try {
      kernels::store_ceilings(set);
    } catch (const std::runtime_error& e) {
      out << "  ceilings not cached: " << e.what() << '\n';
    }
    sets.emplace(b.id, std::move(set));
  }
  if (!sets.empty()) out << "  (stored in " << kernels::ceiling_cache_path() << ")\n\n";
  return sets;
}

// The ceiling section (bench_ceilings.h), then the per-host cache and the load average.
void bench_and_cache_ceilings(const kernels::CpuInfo& cpu, const kernels::Backend& simd, int runs, std::int64_t workers,
                              std::ostream& out) {
  const kernels::CeilingSet ceilings = bench_ceilings(cpu, simd, runs, workers, out);
  try {
    kernels::store_ceilings(ceilings);
    out << "  ceilings stored in " << kernels::ceiling_cache_path() << " (devices and the Kernel Runner show them)\n";
  } catch (const std::runtime_error& e) {
    out << "  ceilings not cached: " << e.what() << '\n';
  }
  out << "load average after the ceilings: " << load_average_text() << '\n';
}

int bench_kernels(const std::vector<std::string>& raw, std::ostream& out) {
  const commands::BenchKernelsSettings settings = commands::bench_kernels_from_words(raw);
  const int runs = settings.runs;
  // Large W, so one run is tens of milliseconds of work and thread start-up (milliseconds on a shared machine) is
  // a small part of it: 16384 workers x 4 points for the throughput variants (~50 ms at 300 GFLOPS), 2048 for the
  // latency-bound paper variants (one dependent chain per worker, ~0.2 s at 10 GFLOPS).
  const std::optional<std::int64_t> w_override = settings.workers;
  const std::string load_before = load_average_text();
  kernels::CpuInfo cpu = cpu_from_isa(settings.isa);
  const auto backends = kernels::available_backends(cpu);
  const kernels::RotationParams params{4, 40000};
  char line[640];
  std::snprintf(line, sizeof line,
                "CPU: %s (%s), %d threads, %.3f GHz measured (dependent imul chain, thread CPU time), %s, "
                "%d FMA pipes assumed, %.0f flop/cycle/core\nload average before: %s\n",
                cpu.model.c_str(), cpu.vendor.c_str(), cpu.threads, cpu.clock_hz / 1e9, cpu.simd.name.c_str(),
                cpu.fma_ports, cpu.flops_per_cycle, load_before.c_str());
  out << line;
  if (settings.ceilings_only) {
    measure_device_ceilings(backends, runs, out);
    bench_and_cache_ceilings(cpu, backends.front(), runs, w_override.value_or(16384), out);
    return 0;
  }
  // Every OpenCL and CUDA device's empirical ceilings first (timed on the device, each result checked), so the
  // table can give each of its rows "% of ceiling" beside "% of the computed peak".
  std::map<std::string, kernels::CeilingSet> device_ceilings;
  if (!settings.no_ceilings) device_ceilings = measure_device_ceilings(backends, runs, out);
  out << "D = 4, N = 40,000; GFLOPS of each of " << runs
      << " runs after one warm-up (wall clock, steady_clock); % of the theoretical peak computed here.\n"
         "'% ceiling': against the device's rotation-mix ceiling measured above (OpenCL, CUDA; the CPU SIMD\n"
         "backend's is paired round by round in its own section below).\n"
         "'% peak/CPU s': the same flops per CPU-second the process got, against one core's peak: the code's\n"
         "efficiency when other processes share the cores (CPU devices only).\n\n";
  std::snprintf(line, sizeof line, "%-34s %-10s %7s %9s %20s %9s %8s %9s %13s\n", "backend", "variant", "W", "median",
                "mean \xC2\xB1 SD (n)", "peak", "% peak", "% ceiling", "% peak/CPU s");
  out << line;
  double simd_best = 0, opencl_best = 0, simd_best_cpu = 0, opencl_best_cpu = 0;
  for (const auto& b : backends) {
    for (const auto v : b.variants) {
      // The single-threaded scalar reference gets 8 workers so the benchmark stays short.
      const std::int64_t workers = b.id == "cpu-scalar"           ? 8
                                   : w_override                   ? *w_override
                                   : v == kernels::Variant::Paper ? 2048
                                                                  : 16384;
      std::vector<double> gflops, cpu_efficiency;
      std::vector<float> outputs;
      b.run_point(params, workers, v, outputs, interrupt_token());  // warm-up
      const double flops = rotation_flop_count(params.dims, params.iterations, workers);
      for (int r = 0; r < runs; ++r) {
        const double c0 = process_cpu_seconds();
        const double t = b.run_point(params, workers, v, outputs, interrupt_token());
        const double cpu_s = process_cpu_seconds() - c0;
        if (kernels::first_wrong_output(outputs, params) >= 0)
          throw std::runtime_error(b.label + " " + b.variant_label(v) + ": output differs from the closed form");
        gflops.push_back(flops / t / 1e9);
        if (per_core_peak(b, cpu) > 0 && cpu_s > 0) cpu_efficiency.push_back(flops / cpu_s / per_core_peak(b, cpu));
      }
      const double g = median(gflops);
      const Summary sum = summarize(gflops);
      const double eff = cpu_efficiency.empty() ? 0 : median(cpu_efficiency);
      if (b.id == "cpu-simd") {
        simd_best = std::max(simd_best, g);
        simd_best_cpu = std::max(simd_best_cpu, eff);
      }
      if (b.id.starts_with("opencl")) {
        opencl_best = std::max(opencl_best, g);
        opencl_best_cpu = std::max(opencl_best_cpu, eff);
      }
      const std::string name =
          b.id.starts_with("opencl") || b.id.starts_with("cuda") ? b.id + " " + b.device_name.substr(0, 24) : b.label;
      char spread[64], eff_text[32];
      std::snprintf(spread, sizeof spread, "%.2f \xC2\xB1 %.2f (%zu)", sum.mean, sum.sd, sum.n);
      if (eff > 0)
        std::snprintf(eff_text, sizeof eff_text, "%.1f%%", 100.0 * eff);
      else
        std::snprintf(eff_text, sizeof eff_text, "n/a");
      char ceiling_text[32] = "n/a";
      if (const auto it = device_ceilings.find(b.id); it != device_ceilings.end() && it->second.rotation_mix.measured())
        std::snprintf(ceiling_text, sizeof ceiling_text, "%.1f%%",
                      100.0 * g * 1e9 / summarize(it->second.rotation_mix.values).mean);
      std::snprintf(line, sizeof line, "%-34s %-10s %7lld %9.2f %21s %9.2f %7.1f%% %9s %13s\n", name.c_str(),
                    b.variant_label(v).c_str(), static_cast<long long>(workers), g, spread,
                    b.theoretical_peak_flops / 1e9, 100.0 * g * 1e9 / b.theoretical_peak_flops, ceiling_text, eff_text);
      out << line;
    }
  }
  out << "(GFLOPS; peak in GFLOPS)\n";
  // Sweep bookkeeping: wall time of a 100-point sweep (the paper's N) against the sum of its timed points. The
  // difference is allocation, initialisation, output checks, progress and result handling.
  const auto& simd = backends.front();
  kernels::SweepSpec spec;
  for (int i = 1; i <= 100; ++i) spec.workers.push_back(64 * i);
  spec.iterations = 40000;
  spec.warmup = false;
  const auto t0 = std::chrono::steady_clock::now();
  const auto result = kernels::run_sweep(simd, cpu, spec, interrupt_token());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double timed = 0;
  for (const auto& s : result.runs.front().samples) timed += s.seconds.front();
  const double clock_after = kernels::calibrate_clock_hz();
  std::snprintf(line, sizeof line,
                "\nsweep of 100 points (W = 64..6400, D = 4, N = 40,000): wall %.3f s, timed kernel %.3f s, "
                "bookkeeping overhead %.2f %%\n"
                "CPU SIMD best: %.2f GFLOPS = %.1f %% of the %.2f GFLOPS theoretical peak (%.1f %% per CPU-second)\n",
                wall, timed, 100.0 * (wall - timed) / wall, simd_best, 100.0 * simd_best * 1e9 / cpu.peak_flops,
                cpu.peak_flops / 1e9, 100.0 * simd_best_cpu);
  out << line;
  if (opencl_best > 0 && simd_best > 0) {
    std::snprintf(line, sizeof line, "OpenCL best / CPU SIMD best: %.2f (%.2f / %.2f GFLOPS; per CPU-second %.2f)\n",
                  opencl_best / simd_best, opencl_best, simd_best,
                  simd_best_cpu > 0 ? opencl_best_cpu / simd_best_cpu : 0.0);
    out << line;
  }
  std::snprintf(line, sizeof line, "clock measured again at the end: %.3f GHz; load average after: %s\n",
                clock_after / 1e9, load_average_text().c_str());
  out << line;
  if (!settings.no_ceilings) bench_and_cache_ceilings(cpu, simd, runs, w_override.value_or(16384), out);
  if (settings.power.sensor != "none") bench_power_overhead(settings, simd, cpu, runs, out);
  return 0;
}

// The power view's min/max decimation on a long trace, against a plain min/max scan of the same samples (the least
// any exact decimation must do) measured in the same run.
int bench_decimate(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {"--samples", "--columns", "--runs"});
  const double n_arg = args.number("--samples", 10'000'000), c_arg = args.number("--columns", 1600),
               r_arg = args.number("--runs", 5);
  if (!(n_arg >= 1000 && n_arg <= 200'000'000)) throw UsageError("--samples must be between 1000 and 200,000,000");
  if (!(c_arg >= 1 && c_arg <= 100'000)) throw UsageError("--columns must be between 1 and 100,000");
  if (!(r_arg >= 1 && r_arg <= 100)) throw UsageError("--runs must be between 1 and 100");
  const auto n = static_cast<std::size_t>(n_arg), columns = static_cast<std::size_t>(c_arg);
  const int runs = static_cast<int>(r_arg);
  // A 10 kHz current log with jittered timestamps and noise, as a power analyser writes.
  std::vector<double> t(n), v(n);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> jitter(0.5e-4, 1.5e-4), noise(-0.3, 0.3);
  double now = 0;
  for (std::size_t i = 0; i < n; ++i) now += jitter(rng), t[i] = now, v[i] = 2.5 + noise(rng);
  using clock = std::chrono::steady_clock;
  const auto ms = [](clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  std::vector<double> whole, zoom, scan;
  std::size_t points_whole = 0, points_zoom = 0;
  double sink = 0;
  for (int r = 0; r < runs + 1; ++r) {  // the first round warms caches and is not counted
    auto t0 = clock::now();
    const DecimatedSeries a = decimate_min_max(t, v, t.front(), t.back(), columns);
    auto t1 = clock::now();
    const DecimatedSeries b = decimate_min_max(t, v, t[n / 4], t[n / 4 + n / 10], columns);  // a tenth in view
    auto t2 = clock::now();
    double mn = v[0], mx = v[0];
    for (double x : v) mn = std::min(mn, x), mx = std::max(mx, x);
    auto t3 = clock::now();
    sink += mn + mx;
    points_whole = a.t.size(), points_zoom = b.t.size();
    if (r == 0) continue;
    whole.push_back(ms(t1 - t0)), zoom.push_back(ms(t2 - t1)), scan.push_back(ms(t3 - t2));
  }
  char line[400];
  std::snprintf(line, sizeof line,
                "min/max decimation of %zu samples into %zu pixel columns, median of %d runs (after one warm-up)\n"
                "  whole trace:       %8.2f ms -> %zu points (at most 2 per column + 2)\n"
                "  a tenth in view:   %8.2f ms -> %zu points\n"
                "  reference, plain min/max scan of all samples: %.2f ms; whole-trace decimation / scan = %.2f\n",
                n, columns, runs, median(whole), points_whole, median(zoom), points_zoom, median(scan),
                median(whole) / std::max(median(scan), 1e-9));
  out << line;
  if (sink == 0.123) out << ' ';  // keeps the reference scan from being optimised away
  return 0;
}

const CommandRegistrar registrar({
    "bench",
    "benchmarks printing figures and ratios (bench kernels | vision | pipeline | tuner | power-csv | decimate | "
    "range-stats | dnn | headroom)",
    "usage: benchscope-cli bench kernels [--runs R] [--workers W] [--isa avx512|avx2|sse4|generic]\n"
    "         [--no-ceilings | --ceilings-only]\n"
    "         (every OpenCL and CUDA device's empirical ceilings are measured first and give the table's\n"
    "          '% ceiling'; the CPU SIMD backend's follow in their own section; all are cached for devices)\n"
    "         [--power SENSOR|auto] [--power-interval-ms M] [--sysfs-root DIR]\n"
    "         (--power: also the sampler's cost, with / without, and the energy per run)\n"
    "       benchscope-cli bench vision [--frames F] [--threads T] [--power SENSOR|auto]\n"
    "       benchscope-cli bench pipeline [--frames N] [--rounds R] [--detect-workers W] [--detect-scale S]\n"
    "         [--power SENSOR|auto]   (vision, pipeline: energy per frame of each method / side; with\n"
    "         --power-interval-ms M and --sysfs-root DIR as for run flops)\n"
    "       benchscope-cli bench tuner [--frames F] [--step S]\n"
    "       benchscope-cli bench power-csv [--rows R] [--runs K]\n"
    "       benchscope-cli bench decimate [--samples N] [--columns C] [--runs K]\n"
    "       benchscope-cli bench range-stats [--samples N] [--updates U]   (the Power tab's selection statistics per\n"
    "         mouse move on an N-sample trace, default 10,000,000, vs a plain rescan of the range)\n" +
        std::string(kBenchDnnUsage) + kBenchHeadroomUsage + kBenchSustainSamplerUsage +
        "  GFLOPS per backend and variant (D = 4, N = 40,000, W workers (default 16384 throughput, 2048 paper),\n"
        "  median and mean \xC2\xB1 SD of R\n"
        "  runs, default 7), % of this machine's theoretical peak (wall clock and per CPU-second), the OpenCL / CPU "
        "SIMD\n"
        "  ratio and the sweep bookkeeping overhead. Then the empirical ceilings measured afresh (rotation mix, FMA,\n"
        "  memory bandwidth; docs/ceilings.md), R rounds alternating with the CPU SIMD throughput variant: mean "
        "\xC2\xB1 SD\n"
        "  (n), % of the computed peak (flagged above it), % of the ceiling, paired ratios (wall clock and per\n"
        "  CPU-second) and whether the 97 % target is met; stored in the per-host cache. --isa forces the CPU SIMD\n"
        "  dispatch (kernel, peak and ceilings) to one instruction set this CPU has. --no-ceilings skips the section;\n"
        "  --ceilings-only runs only it (with the CPU line and the load average).\n"
        "  Figures only: nothing passes or fails on time.\n"
        "  bench vision: preprocessing of a 1280x1024 frame (OpenCV cvtColor + remap, BenchScope's reprojection and "
        "fused\n"
        "  pass), then BenchScope's bilinear and Malvar-He-Cutler demosaics against OpenCV's cvtColor bilinear, 8 and "
        "16\n"
        "  bit, on 1 and on all threads: mean \xC2\xB1 SD (n), medians, ratios, the targets (<= 1x, <= 2x) and the "
        "load average.\n"
        "  bench pipeline: the vision pipeline's stages one after another on one thread vs the concurrent pipeline "
        "with\n"
        "  W detection workers (default: this machine's threads) on R rounds (default 3) of N synthetic paper frames\n"
        "  (default 16), HOG at scale\n"
        "  S (default 0.5); per-stage mean \xC2\xB1 SD (n), both throughputs, their ratio and the theoretical bound, "
        "with 1\n"
        "  OpenCV thread per call on both sides, plus the sequential baseline with OpenCV's default threading.\n" +
        std::string(kBenchDnnHelp) + kBenchHeadroomHelp + kBenchSustainSamplerHelp,
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      return run_subcommand("bench",
                            {{"kernels", out_only<bench_kernels>},
                             {"vision", out_only<bench_vision>},
                             {"pipeline", out_only<bench_pipeline>},
                             {"tuner", out_only<bench_tuner>},
                             {"power-csv", out_only<bench_power_csv>},
                             {"decimate", out_only<bench_decimate>},
                             {"range-stats", out_only<bench_range_stats>},
                             {"dnn", bench_dnn},
                             {"headroom", bench_headroom},
                             {"sustain-sampler", out_only<bench_sustain_sampler>}},
                            args, out, err);
    },
});

}  // namespace
}  // namespace bs::cli
