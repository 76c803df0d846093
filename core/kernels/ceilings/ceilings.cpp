// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/ceilings/ceilings.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>

#include "kernels/backends/backend.h"
#include "kernels/ceilings/triad_cpu.h"
#include "kernels/rotation/rotation.h"
#include "util/host_clock.h"

namespace bs::kernels {

// Per-ISA micro-kernels (ceiling_simd_<isa>.cpp).
#define BS_DECLARE_CEILING(ns)                                                               \
  namespace ns::ceiling {                                                                    \
  int lanes();                                                                               \
  int fma_chains();                                                                          \
  bool rotation_mix(int chains, float* xs, float* ys, std::int64_t steps, float c, float s); \
  bool fma(float* acc, std::int64_t steps, float a, float b);                                \
  }
BS_DECLARE_CEILING(generic)
#if BENCHSCOPE_X86_SIMD
BS_DECLARE_CEILING(sse4)
BS_DECLARE_CEILING(avx2)
BS_DECLARE_CEILING(avx512)
#endif
#undef BS_DECLARE_CEILING

namespace {

struct CeilingFunctions {
  int (*lanes)();
  int (*fma_chains)();
  bool (*mix)(int, float*, float*, std::int64_t, float, float);
  bool (*fma)(float*, std::int64_t, float, float);
};

CeilingFunctions functions_for(Isa isa) {
  switch (isa) {
#if BENCHSCOPE_X86_SIMD
    case Isa::Avx512:
      return {avx512::ceiling::lanes, avx512::ceiling::fma_chains, avx512::ceiling::rotation_mix, avx512::ceiling::fma};
    case Isa::Avx2:
      return {avx2::ceiling::lanes, avx2::ceiling::fma_chains, avx2::ceiling::rotation_mix, avx2::ceiling::fma};
    case Isa::Sse4:
      return {sse4::ceiling::lanes, sse4::ceiling::fma_chains, sse4::ceiling::rotation_mix, sse4::ceiling::fma};
#endif
    default:
      return {generic::ceiling::lanes, generic::ceiling::fma_chains, generic::ceiling::rotation_mix,
              generic::ceiling::fma};
  }
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Per-thread state, 64 floats apart so no two threads share a cache line. Lanes start at distinct angles (and the
// FMA accumulators at distinct values) so that no two chains are the same computation.
constexpr std::size_t kThreadStride = 64 * 32;  // floats: >= 2 x 12 chains x 16 lanes, rounded to cache lines

template <typename Body>
CeilingSample timed_parallel(int threads, double work, Body body) {
  const double c0 = process_cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel num_threads(threads)
  body(omp_get_thread_num());
  CeilingSample s;
  s.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  s.cpu_s = process_cpu_seconds() - c0;
  s.work = work;
  return s;
}

}  // namespace

int ceiling_lanes(Isa isa) { return functions_for(isa).lanes(); }
int ceiling_fma_chains(Isa isa) { return functions_for(isa).fma_chains(); }

std::vector<int> ceiling_mix_chain_options(Isa isa) {
  // x and y per chain + 2 constants + 2 temporaries must fit the register file: 16 registers hold 6 chains.
#if defined(__aarch64__)
  (void)isa;
  return {4, 6, 8, 10, 12};
#else
  if (isa == Isa::Avx512) return {4, 6, 8, 10, 12};
  return {4, 5, 6};
#endif
}

bool ceiling_rotation_mix(Isa isa, int chains, float* xs, float* ys, std::int64_t steps, float c, float s) {
  return functions_for(isa).mix(chains, xs, ys, steps, c, s);
}

bool ceiling_fma(Isa isa, float* acc, std::int64_t steps, float a, float b) {
  return functions_for(isa).fma(acc, steps, a, b);
}

CeilingMeter::CeilingMeter(const SimdTarget& target, int threads, double target_seconds)
    : target_(target), threads_(std::max(threads, 1)) {
  // Sizing and the chain count are decided on this thread alone, timed in its own CPU time: a parallel probe on a
  // shared machine measures the other processes (a descheduled thread, the barrier's spin) more than the code.
  const CeilingFunctions f = functions_for(target.isa);
  std::vector<float> xs(kThreadStride), ys(kThreadStride);
  for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = std::cos(0.01f * i), ys[i] = std::sin(0.01f * i);
  const float c = rotation_cos(), s = rotation_sin();
  // Vector-steps per thread-CPU-second with `k` chains, from runs doubled until they last >= 20 ms.
  const auto mix_rate = [&](int k) {
    for (std::int64_t steps = 1 << 12;; steps *= 2) {
      const double t0 = thread_cpu_seconds();
      f.mix(k, xs.data(), ys.data(), steps, c, s);
      const double t = thread_cpu_seconds() - t0;
      if (t >= 0.02 || steps >= (std::int64_t{1} << 34)) return static_cast<double>(steps) * k / std::max(t, 1e-9);
    }
  };
  // Three tries per count, the best of all kept: other processes only ever slow a try down.
  double best = 0;
  for (int pass = 0; pass < 3; ++pass)
    for (int k : ceiling_mix_chain_options(target.isa))
      if (const double r = mix_rate(k); r > best) best = r, mix_chains_ = k;
  // At most 2e8 steps: the norm's float drift (checked in run_mix) stays far from overflow.
  // Per chain count a repetition runs target_seconds / (number of counts), so all of them take target_seconds.
  const double share = target_seconds / static_cast<double>(ceiling_mix_chain_options(target.isa).size());
  mix_steps_ = std::clamp<std::int64_t>(static_cast<std::int64_t>(best * share / mix_chains_), 1000, 200'000'000);
  if (has_fma()) {
    std::vector<float> acc(kThreadStride, 1.0f);
    for (std::int64_t steps = 1 << 12;; steps *= 2) {
      const double t0 = thread_cpu_seconds();
      f.fma(acc.data(), steps, 0.999f, 0.001f);
      const double t = thread_cpu_seconds() - t0;
      if (t >= 0.02 || steps >= (std::int64_t{1} << 34)) {
        fma_steps_ = std::max<std::int64_t>(
            1000, static_cast<std::int64_t>(static_cast<double>(steps) * target_seconds / std::max(t, 1e-9)));
        break;
      }
    }
  }
}

bool CeilingMeter::has_fma() const { return functions_for(target_.isa).fma_chains() > 0; }

CeilingSample CeilingMeter::run_mix(int chains, std::int64_t steps) {
  const CeilingFunctions f = functions_for(target_.isa);
  const int lanes = f.lanes();
  std::vector<float> state(kThreadStride * static_cast<std::size_t>(threads_));
  for (int t = 0; t < threads_; ++t)
    for (int i = 0; i < chains * lanes; ++i) {
      const double angle = 0.001 * (t * 997 + i);
      state[t * kThreadStride + static_cast<std::size_t>(i)] = static_cast<float>(std::cos(angle));
      state[t * kThreadStride + kThreadStride / 2 + static_cast<std::size_t>(i)] = static_cast<float>(std::sin(angle));
    }
  const float c = rotation_cos(), s = rotation_sin();
  const double flops = 6.0 * lanes * chains * static_cast<double>(steps) * threads_;
  bool ok = true;
  const CeilingSample sample = timed_parallel(threads_, flops, [&](int t) {
    float* xs = state.data() + static_cast<std::size_t>(t) * kThreadStride;
    if (!f.mix(chains, xs, xs + kThreadStride / 2, steps, c, s)) ok = false;
  });
  if (!ok) throw std::invalid_argument("rotation-mix ceiling: no kernel for " + std::to_string(chains) + " chains");
  // Each step scales |(x, y)|^2 by c^2 + s^2 of the float constants (1 - 6e-8 or so, which compounds over millions
  // of steps): a final norm off that expectation means the kernel did not run the steps it is counted for.
  const double per_step = std::log(static_cast<double>(c) * c + static_cast<double>(s) * s);
  for (int t = 0; t < threads_; ++t) {
    const double x = state[t * kThreadStride], y = state[t * kThreadStride + kThreadStride / 2];
    if (!(std::fabs(std::log(x * x + y * y) - per_step * static_cast<double>(steps)) < 0.1))
      throw std::runtime_error("rotation-mix ceiling: the final state is not that of " + std::to_string(steps) +
                               " steps");
  }
  return sample;
}

CeilingSample CeilingMeter::run_fma(std::int64_t steps) {
  const CeilingFunctions f = functions_for(target_.isa);
  const int lanes = f.lanes(), chains = f.fma_chains();
  std::vector<float> acc(kThreadStride * static_cast<std::size_t>(threads_));
  for (std::size_t i = 0; i < acc.size(); ++i) acc[i] = 1.0f + 0.001f * static_cast<float>(i % 1000);
  const double flops = 2.0 * lanes * chains * static_cast<double>(steps) * threads_;
  // a < 1: every accumulator converges to b / (1 - a) = 1 and stays there, finite.
  const CeilingSample sample = timed_parallel(threads_, flops, [&](int t) {
    f.fma(acc.data() + static_cast<std::size_t>(t) * kThreadStride, steps, 0.999f, 0.001f);
  });
  if (!std::isfinite(acc[0])) throw std::runtime_error("FMA ceiling: accumulator is not finite");
  return sample;
}

CeilingSample CeilingMeter::time_rotation_mix() {
  // Every chain count the register file holds, each for the same number of vector operations; the fastest per
  // CPU-second is this repetition's ceiling. On a loaded machine one short probe cannot rank 5 against 6 chains
  // (their difference is below the noise), and a ceiling from the wrong count would flatter the kernel.
  CeilingSample best;
  for (int k : ceiling_mix_chain_options(target_.isa)) {
    const CeilingSample s = run_mix(k, std::max<std::int64_t>(1000, mix_steps_ * mix_chains_ / k));
    if (s.rate_per_cpu_s() > best.rate_per_cpu_s()) best = s, last_best_chains_ = k;
  }
  return best;
}

CeilingSample CeilingMeter::time_fma() { return has_fma() ? run_fma(fma_steps_) : CeilingSample{}; }

std::string CeilingMeter::mix_how() const {
  char text[512];
  std::snprintf(text, sizeof text,
                "rotation mix: %d threads, each with %s independent chains of %d-lane %s vectors in registers (per "
                "repetition the fastest count per CPU-second; last: %d), ~%lld vector-steps each, 2 mul + FMS + FMA "
                "per step, 6 flops per lane-step, no memory traffic",
                threads_, options_text().c_str(), functions_for(target_.isa).lanes(), target_.name.c_str(),
                last_best_chains_ ? last_best_chains_ : mix_chains_, static_cast<long long>(mix_steps_ * mix_chains_));
  return text;
}

std::string CeilingMeter::options_text() const {
  std::string text;
  for (int k : ceiling_mix_chain_options(target_.isa)) text += (text.empty() ? "" : "/") + std::to_string(k);
  return text;
}

std::string CeilingMeter::fma_how() const {
  if (!has_fma()) return "FMA: " + target_.name + " has no FMA instruction";
  char text[300];
  std::snprintf(text, sizeof text,
                "FMA: %d threads x %d independent accumulators acc = acc * a + b of %d-lane %s vectors, %lld steps, "
                "2 flops per lane and FMA",
                threads_, functions_for(target_.isa).fma_chains(), functions_for(target_.isa).lanes(),
                target_.name.c_str(), static_cast<long long>(fma_steps_));
  return text;
}

CeilingSample time_bandwidth(std::size_t mib_per_array, const CancelToken& cancel) {
  const std::size_t elements = mib_per_array * (std::size_t{1} << 20) / sizeof(float);
  const double c0 = process_cpu_seconds();
  CeilingSample s;
  s.wall_s = cpu_triad_seconds(elements, true, cancel);
  // CPU time includes the arrays' first-touch initialisation; the wall figure times only the triad pass.
  s.cpu_s = process_cpu_seconds() - c0;
  s.work = 12.0 * static_cast<double>(elements);
  return s;
}

CeilingSet measure_ceilings(const CpuInfo& cpu, const CeilingSpec& spec, const CancelToken& cancel,
                            const ProgressFn& progress) {
  if (spec.repeats < 1 || spec.repeats > 1000) throw std::invalid_argument("ceiling repeats must be 1 to 1000");
  CeilingSet set;
  set.host = host_name();
  set.cpu_model = cpu.model;
  set.backend = "CPU SIMD (" + cpu.simd.name + ")";
  set.isa = isa_id(cpu.simd.isa);
  set.threads = cpu.threads;
  set.clock_hz = cpu.clock_hz;
  set.computed_peak_flops = cpu.peak_flops;
  set.date = utc_timestamp();
  if (progress) progress(0.0, "choosing the chain count");
  cancel.throw_if_cancelled();
  CeilingMeter meter(cpu.simd, cpu.threads);
  set.rotation_mix.unit = set.fma.unit = "FLOP/s";
  set.bandwidth.unit = "B/s";
  set.rotation_mix.how = meter.mix_how();
  set.fma.how = meter.fma_how();
  const auto add = [](Ceiling& c, const CeilingSample& s) {
    if (s.work <= 0) return;
    c.values.push_back(s.rate());
    c.per_cpu_second.push_back(s.rate_per_cpu_s());
  };
  for (int r = 0; r < spec.repeats; ++r) {  // alternating, so a burst of load hits every ceiling alike
    if (progress) progress(static_cast<double>(r) / spec.repeats, "repetition " + std::to_string(r + 1));
    cancel.throw_if_cancelled();
    add(set.rotation_mix, meter.time_rotation_mix());
    add(set.fma, meter.time_fma());
    if (spec.bandwidth) add(set.bandwidth, time_bandwidth(spec.bandwidth_mib_per_array, cancel));
  }
  if (spec.bandwidth)
    set.bandwidth.how = "STREAM triad a = b + q c over 3 arrays of " + std::to_string(spec.bandwidth_mib_per_array) +
                        " MiB, " + std::to_string(cpu.threads) + " threads, 12 bytes per element";
  if (progress) progress(1.0, "done");
  return set;
}

std::string device_ceiling_family(const Backend& backend) { return backend.id.substr(0, backend.id.find(':')); }

CeilingSet measure_device_ceilings(const Backend& backend, const CeilingSpec& spec, const CancelToken& cancel,
                                   const ProgressFn& progress) {
  if (!backend.ceiling_kernels)
    throw std::invalid_argument(backend.id + ": no empirical-ceiling micro-kernels for this backend");
  if (spec.repeats < 1 || spec.repeats > 1000) throw std::invalid_argument("ceiling repeats must be 1 to 1000");
  CeilingSet set;
  set.host = host_name();
  set.cpu_model = backend.device_name;
  set.backend = backend.label;
  set.isa = device_ceiling_family(backend);
  set.threads = 0;
  set.kind = backend.kind;
  set.computed_peak_flops = backend.theoretical_peak_flops;
  set.date = utc_timestamp();
  if (progress) progress(0.0, "sizing the device micro-kernels");
  cancel.throw_if_cancelled();
  const std::unique_ptr<DeviceCeilingKernels> kernels = backend.ceiling_kernels(spec);
  set.rotation_mix.unit = set.fma.unit = "FLOP/s";
  set.bandwidth.unit = "B/s";
  // Device time only: per_cpu_second stays empty (the host's CPU time says nothing about the device's work).
  const auto add = [](Ceiling& c, const CeilingSample& s) {
    if (s.work > 0 && s.wall_s > 0) c.values.push_back(s.rate());
  };
  for (int r = 0; r < spec.repeats; ++r) {
    if (progress) progress(static_cast<double>(r) / spec.repeats, "repetition " + std::to_string(r + 1));
    cancel.throw_if_cancelled();
    add(set.rotation_mix, kernels->rotation_mix());
    cancel.throw_if_cancelled();
    add(set.fma, kernels->fma());
    if (spec.bandwidth) {
      cancel.throw_if_cancelled();
      add(set.bandwidth, kernels->bandwidth());
    }
  }
  set.rotation_mix.how = kernels->mix_how();
  set.fma.how = kernels->fma_how();
  if (spec.bandwidth) set.bandwidth.how = kernels->bandwidth_how();
  if (progress) progress(1.0, "done");
  return set;
}

ResultSet ceiling_result_set(const CeilingSet& c) {
  ResultSet set;
  set.platform = c.host;
  set.device = c.cpu_model;
  set.device_kind = c.kind;
  set.backend = c.backend;
  set.source_format = kCeilingSource;
  set.provenance.origin = DataOrigin::Measured;
  set.provenance.host = c.host;
  if (c.kind == DeviceKind::Gpu)
    set.provenance.gpu_model = c.cpu_model;
  else
    set.provenance.cpu_model = c.cpu_model;
  set.provenance.os = os_name();
  set.provenance.compiler = BENCHSCOPE_COMPILER;
  set.provenance.tool = std::string("benchscope ") + BENCHSCOPE_VERSION;
  set.provenance.date = c.date;
  char note[200];
  if (c.threads > 0)
    std::snprintf(note, sizeof note, "empirical ceilings, %d threads, %.3f GHz measured, computed peak %.4g FLOP/s; ",
                  c.threads, c.clock_hz / 1e9, c.computed_peak_flops);
  else
    std::snprintf(note, sizeof note, "empirical ceilings of the %s device, computed peak %.4g FLOP/s; ",
                  c.backend.c_str(), c.computed_peak_flops);
  set.provenance.note =
      note + c.rotation_mix.how + "; " + c.fma.how + (c.bandwidth.measured() ? "; " + c.bandwidth.how : "");
  const auto add = [&](const Ceiling& ceil, std::string name, std::string metric) {
    if (!ceil.measured()) return;
    Measurement m;
    m.name = std::move(name);
    m.metric = std::move(metric);
    m.unit = ceil.unit;
    m.values = ceil.values;
    set.measurements.push_back(std::move(m));
  };
  add(c.rotation_mix, "rotation-mix/" + c.isa, kRotationMixMetric);
  add(c.fma, "fma/" + c.isa, kFmaMetric);
  add(c.bandwidth, c.threads > 0 ? "stream-triad/ceiling" : "device-copy/" + c.isa, "bandwidth");
  return set;
}

}  // namespace bs::kernels
