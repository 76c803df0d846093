// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Empirical ceilings of a CPU device, measured by BenchScope's own micro-kernels at run time (as the Empirical
// Roofline Toolkit measures peaks), beside the computed peak of cpu_info.h, which is a model and can be wrong in
// either direction (on an AMD EPYC with AVX-512 the rotation kernel reached 115-121 % of it):
//  - rotation mix: the rotation kernel's own instructions (2 mul + FMS + FMA per vector and step) on enough
//    independent chains held in registers, one group per thread, no memory traffic; 6 counted flops per lane-step;
//  - FMA: independent acc = acc * a + b chains; 2 counted flops per lane and FMA (absent without FMA);
//  - memory bandwidth: the STREAM triad of triad_cpu.h over arrays far beyond the caches, 12 bytes per element.
// Every repetition is timed by the wall clock (all threads) and by the process's CPU time, so a ratio taken on a
// shared, loaded machine can compare work per CPU-second. How each is obtained: docs/ceilings.md.
#include <optional>
#include <string>
#include <vector>

#include "analysis/peaks/peak_ceilings.h"
#include "kernels/cpu/cpu_info.h"
#include "model/flops_run.h"
#include "util/cancel.h"

namespace bs::kernels {

using bs::kCeilingSource;
using bs::kFmaMetric;
using bs::kRotationMixMetric;

// One timed repetition: `work` flops (or bytes) done in `wall_s` seconds by all threads, using `cpu_s` seconds of
// the process's CPU time.
struct CeilingSample {
  double work = 0, wall_s = 0, cpu_s = 0;
  double rate() const { return wall_s > 0 ? work / wall_s : 0; }
  double rate_per_cpu_s() const { return cpu_s > 0 ? work / cpu_s : 0; }
};

struct Ceiling {
  std::string unit;                    // "FLOP/s" or "B/s"
  std::vector<double> values;          // per repetition, wall clock
  std::vector<double> per_cpu_second;  // per repetition, work per CPU-second (FLOP or B per CPU-s)
  std::string how;                     // the micro-kernel and its parameters, for provenance and tooltips
  bool measured() const { return !values.empty(); }
};

struct CeilingSet {
  std::string host, cpu_model, backend;  // backend: the CPU SIMD label, e.g. "CPU SIMD (AVX2+FMA)"; a device's: "CUDA"
  std::string isa;                       // isa_id(): "avx512", "avx2", ...; a device's: "cuda" or "opencl"
  int threads = 0;                       // 0 for a device (OpenCL, CUDA): cpu_model then holds the device's name
  DeviceKind kind = DeviceKind::Cpu;     // Gpu for a GPU's ceilings (an OpenCL CPU device: Cpu)
  double clock_hz = 0;                   // measured before the ceilings (dependent imul chain)
  double computed_peak_flops = 0;        // the model's peak for this ISA (cpu_info.h), for the comparison
  std::string date;                      // UTC, ISO 8601
  Ceiling rotation_mix, fma, bandwidth;  // fma empty without FMA; bandwidth empty when not asked for
};

// Times the two FLOP micro-kernels on `threads` threads for one ISA. The constructor, on the calling thread and
// in its CPU time, picks the rotation mix's chain count (the fastest of the counts its register file can hold,
// each tried three times) and sizes a repetition to about `target_seconds` of CPU time per thread (~0.5 s in all).
class CeilingMeter {
 public:
  CeilingMeter(const SimdTarget& target, int threads, double target_seconds = 0.1);
  int mix_chains() const { return mix_chains_; }  // the fastest count in the constructor's probes
  bool has_fma() const;
  CeilingSample time_rotation_mix();  // the fastest of all offered chain counts, each run once
  int last_best_chains() const { return last_best_chains_; }
  CeilingSample time_fma();  // work 0 when the ISA has no FMA
  std::string mix_how() const;
  std::string fma_how() const;

 private:
  CeilingSample run_mix(int chains, std::int64_t steps);
  CeilingSample run_fma(std::int64_t steps);
  std::string options_text() const;  // "4/5/6"
  SimdTarget target_;
  int threads_;
  int mix_chains_ = 0, last_best_chains_ = 0;
  std::int64_t mix_steps_ = 0, fma_steps_ = 0;
};

// One repetition of the memory-bandwidth ceiling: a triad pass over three arrays of `mib_per_array` MiB.
CeilingSample time_bandwidth(std::size_t mib_per_array, const CancelToken& cancel);

struct CeilingSpec {
  int repeats = 5;
  bool bandwidth = true;
  std::size_t bandwidth_mib_per_array = 64;  // 192 MiB in all: beyond any L3 of a robot computer
  // Devices (OpenCL, CUDA): seconds of device time per micro-kernel and repetition, and the copy buffers' size
  // (0: 256 MiB each on a GPU, 64 MiB on an OpenCL CPU device, at most an eighth of the device's memory).
  double device_target_seconds = 0.1;
  std::size_t device_copy_mib = 0;
};

// The micro-kernels of a device backend (OpenCL, CUDA): each call is one repetition, timed on the device
// (work in flops or bytes, wall_s the device time, cpu_s 0: the host's CPU time says nothing about a GPU) and its
// result checked (std::runtime_error naming what is wrong):
//  - FMA: acc = acc * 1 + 2^-10 on independent accumulators, every value exact, so each must equal its start plus
//    steps * 2^-10;
//  - rotation mix: the rotation kernel's 2 mul + 2 FMA per point-step on independent points per work-item (6
//    counted flops), every point's final angle and norm those of the counted steps;
//  - bandwidth: a device-memory copy between two buffers (2 x size bytes per pass), the target cleared before and
//    compared with the source after.
class DeviceCeilingKernels {
 public:
  virtual ~DeviceCeilingKernels() = default;
  virtual CeilingSample fma() = 0;
  virtual CeilingSample rotation_mix() = 0;
  virtual CeilingSample bandwidth() = 0;
  virtual std::string fma_how() const = 0;
  virtual std::string mix_how() const = 0;
  virtual std::string bandwidth_how() const = 0;
};

struct Backend;

// The ceilings of a device backend (Backend::ceiling_kernels set), repetitions alternating between the kernels:
// host, cpu_model = the device's name, backend = its label, isa = "cuda" / "opencl", threads 0, computed peak =
// the backend's theoretical peak. std::invalid_argument for a backend without ceiling kernels; throws Cancelled.
CeilingSet measure_device_ceilings(const Backend& backend, const CeilingSpec& spec, const CancelToken& cancel,
                                   const ProgressFn& progress = {});

// "cuda" for "cuda:0", "opencl" for "opencl:1": the ISA field of a device's ceilings.
std::string device_ceiling_family(const Backend& backend);

// All ceilings of this CPU with cpu.simd, repetitions alternating between the micro-kernels. Throws Cancelled.
CeilingSet measure_ceilings(const CpuInfo& cpu, const CeilingSpec& spec, const CancelToken& cancel,
                            const ProgressFn& progress = {});

// As a result set (source kCeilingSource) for a workspace, so views of that device show "% of empirical
// ceiling": measurements "rotation-mix/<isa>" (FLOP/s), "fma/<isa>" (FLOP/s) and "stream-triad/..." (B/s,
// metric "bandwidth": also the roofline's memory ceiling); provenance says when and how.
ResultSet ceiling_result_set(const CeilingSet& set);

// Raw single-thread access for tests: false when the ISA has no such kernel (or `chains` is not offered).
int ceiling_lanes(Isa isa);
std::vector<int> ceiling_mix_chain_options(Isa isa);  // chain counts the rotation mix is compiled for
int ceiling_fma_chains(Isa isa);                      // 0 without FMA
bool ceiling_rotation_mix(Isa isa, int chains, float* xs, float* ys, std::int64_t steps, float c, float s);
bool ceiling_fma(Isa isa, float* acc, std::int64_t steps, float a, float b);

}  // namespace bs::kernels
