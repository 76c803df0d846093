// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <optional>
#include <string>

#include "kernels/cpu/arm_cores.h"
#include "kernels/rotation/rotation_simd.h"

namespace bs::kernels {

struct CpuInfo {
  std::string model;    // /proc/cpuinfo "model name" (or "unknown CPU")
  int threads = 1;      // OpenMP threads the kernels use
  double clock_hz = 0;  // sustained clock measured by calibrate_clock_hz()
  SimdTarget simd;      // the ISA the SIMD backend uses
  std::string vendor;   // "GenuineIntel", "AuthenticAMD", ...
  // Full-width FP ops per cycle: 2 pipes on Intel since Haswell, Zen, Apple and Neoverse cores; AMD Zen 4 splits a
  // 512-bit op over both 256-bit pipes, so AVX-512 there retires one zmm op per cycle (Zen 5 does not).
  int fma_ports = 2;
  // Whether FP adds have pipes of their own (AMD Zen: FADD pipes 2-3 beside the FMUL/FMA pipes 0-1). Intel cores
  // run mul, add and FMA on the same ports. Matters only for code without FMA (the scalar reference, SSE4).
  bool separate_add_pipes = false;
  double flops_per_cycle = 0;  // this kernel's counted flops per cycle per core (SIMD backend)
  double peak_flops = 0;       // threads * clock * flops_per_cycle
  // ARM: the core types by name, per cluster (arm_cores.h); then fma_ports, flops_per_cycle and peak_flops follow
  // each cluster's core type and clock (cpufreq's maximum where readable, else the measured clock).
  std::optional<ArmCpu> arm;
};

// Measures the clock with a dependent chain of 64-bit multiplies (3 cycles latency on every x86 core since
// Sandy Bridge and on AMD Zen 1-5; a chain of adds is folded by some cores and overstates it), timed in this
// thread's CPU time so that other processes on a shared machine do not make it look slower. Best of 5, ~0.2 s.
// On other architectures the same loop gives an estimate that assumes the same 3-cycle latency.
double calibrate_clock_hz();

// Counted flops (6 per point-step) per cycle per core for a vector of `lanes` floats:
//  - with FMA, one step of a vector is 2 mul + 2 FMA = 4 ops, all on the `fma_ports` mul/FMA pipes:
//    lanes * 6 * ports / 4 (AVX-512 with 2 ports: 48, AVX2: 24, NEON: 12);
//  - without FMA it is 4 mul + 2 add: with separate add pipes the 4 muls bound it (lanes * 6 * ports / 4),
//    on shared ports all 6 ops do (lanes * 6 * ports / 6).
double rotation_flops_per_cycle(int lanes, bool fma, int fma_ports, bool separate_add_pipes);

// Model, vendor, threads, best ISA and, when `calibrate`, the measured clock and the SIMD kernel's peak
// = threads * clock * flops_per_cycle. On ARM the model names the board and the core types ("Raspberry Pi 5 Model B
// Rev 1.0: 4x Cortex-A76"), and the peak is the sum over clusters of cores * clock * flops per cycle of that core.
CpuInfo detect_cpu(bool calibrate = true);

// The same CPU with the SIMD backend forced to `target` (`--isa`): its lanes, FMA pipes, flops per cycle and peak.
void use_simd_target(CpuInfo& cpu, const SimdTarget& target);

std::string os_name();  // PRETTY_NAME of /etc/os-release

}  // namespace bs::kernels
