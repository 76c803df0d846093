// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>

#include "kernels/rotation_simd.h"

namespace bs::kernels {

struct CpuInfo {
  std::string model;          // /proc/cpuinfo "model name" (or "unknown CPU")
  int threads = 1;            // OpenMP threads the kernels use
  double clock_hz = 0;        // sustained clock measured by calibrate_clock_hz()
  SimdTarget simd;            // the ISA the SIMD backend uses
  std::string vendor;         // "GenuineIntel", "AuthenticAMD", ...
  // Full-width FP ops per cycle: 2 pipes on Intel since Haswell, Zen, Apple and Neoverse cores; AMD Zen 4 splits a
  // 512-bit op over both 256-bit pipes, so AVX-512 there retires one zmm op per cycle (Zen 5 does not).
  int fma_ports = 2;
  double flops_per_cycle = 0; // this kernel's counted flops per cycle per core
  double peak_flops = 0;      // threads * clock * flops_per_cycle
};

// Measures the clock with a dependent chain of 64-bit multiplies (3 cycles latency on every x86 core since
// Sandy Bridge; a chain of adds is folded by some cores and overstates it). Takes ~0.1 s.
double calibrate_clock_hz();

// The rotation kernel's peak: one vector step is 2 mul + 2 FMA (or 2 mul + add + sub without FMA) = 4 FP ops on
// `fma_ports` pipes for lanes * 6 counted flops, so flops/cycle/core = lanes * 6 * ports / 4
// (AVX-512: 48, AVX2: 24, SSE/NEON: 12).
CpuInfo detect_cpu(bool calibrate = true);

std::string host_name();
std::string os_name();  // PRETTY_NAME of /etc/os-release

}  // namespace bs::kernels
