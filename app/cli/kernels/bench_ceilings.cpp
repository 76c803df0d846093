// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/bench_ceilings.h"

#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "analysis/peaks/ceiling_check.h"
#include "analysis/peaks/flops.h"
#include "analysis/stats/stats.h"
#include "analysis/stats/units.h"
#include "common/bench_host.h"
#include "common/signals.h"
#include "util/host_clock.h"

namespace bs::cli {
namespace {

std::string spread(const std::vector<double>& v, double scale, const char* unit) {
  const Summary s = summarize(v);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.2f \xC2\xB1 %.2f %s (n = %zu)", s.mean / scale, s.sd / scale, unit, s.n);
  return buf;
}

std::string per_cpu_text(const std::vector<double>& per_cpu_second) {
  return per_cpu_second.empty() ? std::string() : ", " + spread(per_cpu_second, 1e9, "GFLOP per CPU-s");
}

void print_flags(const std::vector<PlausibilityFlag>& flags, std::ostream& out, const char* indent) {
  for (const PlausibilityFlag& f : flags) out << indent << "  \xE2\x9A\xA0 " << f.code << ": " << f.reason << '\n';
}

}  // namespace

void print_ceilings(const kernels::CeilingSet& set, std::ostream& out, const char* indent) {
  char line[400];
  if (set.rotation_mix.measured()) {
    const double mean = summarize(set.rotation_mix.values).mean;
    auto cmp = compare_to_ceilings(mean, set.computed_peak_flops, std::nullopt, "the rotation-mix ceiling");
    // A device's ceilings (threads 0) are timed on the device: no per-CPU-second figure.
    std::snprintf(line, sizeof line, "%srotation-mix ceiling: %s%s; %s of the computed peak %.2f GFLOPS\n", indent,
                  spread(set.rotation_mix.values, 1e9, "GFLOPS").c_str(),
                  per_cpu_text(set.rotation_mix.per_cpu_second).c_str(),
                  fraction_text(cmp.fraction_of_peak, !cmp.flags.empty()).c_str(), set.computed_peak_flops / 1e9);
    out << line;
    // Per CPU-second against one core's computed peak: the figure that other processes on the cores do not lower.
    if (set.threads > 0 && !set.rotation_mix.per_cpu_second.empty()) {
      const auto per_core =
          compare_to_ceilings(summarize(set.rotation_mix.per_cpu_second).mean, set.computed_peak_flops / set.threads,
                              std::nullopt, "the rotation-mix ceiling per CPU-second");
      std::snprintf(line, sizeof line, "%s  per CPU-second: %s of one core's computed peak %.2f GFLOPS\n", indent,
                    fraction_text(per_core.fraction_of_peak, !per_core.flags.empty()).c_str(),
                    set.computed_peak_flops / set.threads / 1e9);
      out << line;
      cmp.flags.insert(cmp.flags.end(), per_core.flags.begin(), per_core.flags.end());
    }
    out << indent << "  how: " << set.rotation_mix.how << '\n';
    print_flags(cmp.flags, out, indent);
  }
  if (set.fma.measured()) {
    std::snprintf(line, sizeof line, "%sFMA ceiling: %s%s\n", indent, spread(set.fma.values, 1e9, "GFLOPS").c_str(),
                  per_cpu_text(set.fma.per_cpu_second).c_str());
    out << line << indent << "  how: " << set.fma.how << '\n';
  } else {
    out << indent << "FMA ceiling: not measured (" << set.fma.how << ")\n";
  }
  if (set.bandwidth.measured()) {
    std::snprintf(line, sizeof line, "%s%s bandwidth ceiling: %s\n", indent,
                  set.threads > 0 ? "memory" : "device memory", spread(set.bandwidth.values, 1e9, "GB/s").c_str());
    out << line << indent << "  how: " << set.bandwidth.how << '\n';
  }
}

kernels::CeilingSet bench_ceilings(const kernels::CpuInfo& cpu, const kernels::Backend& simd, int rounds,
                                   std::int64_t workers, std::ostream& out) {
  const kernels::RotationParams params{4, 40000};
  kernels::CeilingSet set;
  set.host = bs::host_name();
  set.cpu_model = cpu.model;
  set.backend = simd.label;
  set.isa = kernels::isa_id(cpu.simd.isa);
  set.threads = cpu.threads;
  set.clock_hz = cpu.clock_hz;
  set.computed_peak_flops = cpu.peak_flops;
  set.date = bs::utc_timestamp();
  kernels::CeilingMeter meter(cpu.simd, cpu.threads);
  set.rotation_mix.unit = set.fma.unit = "FLOP/s";
  set.bandwidth.unit = "B/s";
  set.rotation_mix.how = meter.mix_how();
  set.fma.how = meter.fma_how();
  constexpr std::size_t kTriadMiB = 64;
  set.bandwidth.how = "STREAM triad a = b + q c over 3 arrays of " + std::to_string(kTriadMiB) + " MiB, " +
                      std::to_string(cpu.threads) + " threads, 12 bytes per element";
  const double flops = rotation_flop_count(params.dims, params.iterations, workers);
  std::vector<double> kernel_wall, kernel_cpu, ratio_wall, ratio_cpu;
  std::vector<float> outputs;
  simd.run_point(params, workers, kernels::Variant::Throughput, outputs, interrupt_token());  // warm-up
  const auto add = [](kernels::Ceiling& c, const kernels::CeilingSample& s) {
    if (s.work <= 0) return;
    c.values.push_back(s.rate());
    c.per_cpu_second.push_back(s.rate_per_cpu_s());
  };
  for (int r = 0; r < rounds; ++r) {  // kernel, then each ceiling: adjacent in time, so one round's load hits all
    interrupt_token().throw_if_cancelled();
    const double c0 = process_cpu_seconds();
    const double t = simd.run_point(params, workers, kernels::Variant::Throughput, outputs, interrupt_token());
    const double cpu_s = process_cpu_seconds() - c0;
    if (kernels::first_wrong_output(outputs, params) >= 0)
      throw std::runtime_error(simd.label + " throughput: output differs from the closed form");
    kernel_wall.push_back(flops / t);
    kernel_cpu.push_back(flops / cpu_s);
    const kernels::CeilingSample mix = meter.time_rotation_mix();
    add(set.rotation_mix, mix);
    ratio_wall.push_back(kernel_wall.back() / mix.rate());
    ratio_cpu.push_back(kernel_cpu.back() / mix.rate_per_cpu_s());
    add(set.fma, meter.time_fma());
    add(set.bandwidth, kernels::time_bandwidth(kTriadMiB, interrupt_token()));
  }
  out << "\nempirical ceilings of " << cpu.model << " with " << cpu.simd.name << ", " << cpu.threads
      << " threads, measured now, " << rounds << " rounds alternating the throughput variant (W = " << workers
      << ") / rotation mix / FMA / triad:\n";
  print_ceilings(set, out);
  const double k_mean = summarize(kernel_wall).mean, mix_mean = summarize(set.rotation_mix.values).mean;
  const auto cmp = compare_to_ceilings(k_mean, cpu.peak_flops, mix_mean, "the throughput variant",
                                       "rotation mix, measured in the same rounds");
  char line[500];
  std::snprintf(line, sizeof line,
                "  throughput variant: %s, %s; %s of the computed peak; %s of the "
                "rotation-mix ceiling\n",
                spread(kernel_wall, 1e9, "GFLOPS").c_str(), spread(kernel_cpu, 1e9, "GFLOP per CPU-s").c_str(),
                fraction_text(cmp.fraction_of_peak, !cmp.flags.empty()).c_str(),
                fraction_text(cmp.fraction_of_ceiling, !cmp.flags.empty()).c_str());
  out << line;
  print_flags(cmp.flags, out, "  ");
  const Summary rw = summarize(ratio_wall), rc = summarize(ratio_cpu);
  std::snprintf(line, sizeof line,
                "  throughput variant / rotation-mix ceiling, paired by round: wall clock %.1f \xC2\xB1 %.1f %%, "
                "per CPU-second %.1f \xC2\xB1 %.1f %% (n = %zu)\n",
                100 * rw.mean, 100 * rw.sd, 100 * rc.mean, 100 * rc.sd, rc.n);
  out << line;
  std::snprintf(line, sizeof line,
                "  target: throughput variant >= 97 %% of the rotation-mix ceiling (%s): wall clock %s, per "
                "CPU-second %s\n",
                cpu.simd.name.c_str(), rw.mean >= 0.97 ? "MET" : "NOT MET", rc.mean >= 0.97 ? "MET" : "NOT MET");
  out << line;
  return set;
}

}  // namespace bs::cli
