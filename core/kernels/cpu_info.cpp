// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/cpu_info.h"

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <fstream>

namespace bs::kernels {
namespace {

std::string read_key(const char* path, const std::string& key, char sep) {
  std::ifstream f(path);
  std::string line;
  while (std::getline(f, line)) {
    if (line.rfind(key, 0) != 0) continue;
    const auto pos = line.find(sep);
    if (pos == std::string::npos) continue;
    std::string v = line.substr(pos + 1);
    while (!v.empty() && (v.front() == ' ' || v.front() == '\t' || v.front() == '"')) v.erase(v.begin());
    while (!v.empty() && (v.back() == '"' || v.back() == ' ')) v.pop_back();
    return v;
  }
  return {};
}

}  // namespace

double calibrate_clock_hz() {
  constexpr std::int64_t kIterations = 20'000'000;
  constexpr int kUnroll = 8;
  constexpr double kCyclesPerMul = 3.0;
  volatile std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  volatile std::uint64_t factor = 0xBF58476D1CE4E5B9ull;
  double best = 0;
  for (int attempt = 0; attempt < 3; ++attempt) {  // best of 3: the shared VM sometimes steals time
    std::uint64_t x = seed;
    const std::uint64_t m = factor;
    const auto t0 = std::chrono::steady_clock::now();
    for (std::int64_t i = 0; i < kIterations; ++i) {
      for (int u = 0; u < kUnroll; ++u) x *= m;  // each multiply waits for the previous one
      asm volatile("" : "+r"(x));                // keep the chain: no reassociation into a power of m
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    seed = x;
    const double hz = kCyclesPerMul * kUnroll * static_cast<double>(kIterations) / s;
    if (hz > best) best = hz;
  }
  return best;
}

CpuInfo detect_cpu(bool calibrate) {
  CpuInfo info;
  info.model = read_key("/proc/cpuinfo", "model name", ':');
  if (info.model.empty()) info.model = read_key("/proc/cpuinfo", "Model", ':');
  if (info.model.empty()) info.model = "unknown CPU";
  info.threads = omp_get_max_threads();
  info.vendor = read_key("/proc/cpuinfo", "vendor_id", ':');
  info.simd = best_simd_target();
  // Zen 4 (family 25) double-pumps 512-bit ops on 256-bit pipes; Zen 5 (family 26) has full-width pipes.
  if (info.vendor == "AuthenticAMD" && info.simd.isa == Isa::Avx512 &&
      read_key("/proc/cpuinfo", "cpu family", ':') == "25")
    info.fma_ports = 1;
  info.flops_per_cycle = info.simd.lanes * 6.0 * info.fma_ports / 4.0;
  if (calibrate) {
    info.clock_hz = calibrate_clock_hz();
    info.peak_flops = info.threads * info.clock_hz * info.flops_per_cycle;
  }
  return info;
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown host";
  return buf;
}

std::string os_name() {
  const std::string name = read_key("/etc/os-release", "PRETTY_NAME", '=');
  return name.empty() ? "unknown OS" : name;
}

}  // namespace bs::kernels
