// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/cpu/cpu_info.h"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <ctime>
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

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

double calibrate_clock_hz() {
  constexpr std::int64_t kIterations = 4'000'000;
  constexpr int kUnroll = 8;
  constexpr double kCyclesPerMul = 3.0;
  volatile std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  volatile std::uint64_t factor = 0xBF58476D1CE4E5B9ull;
  double best = 0;
  for (int attempt = 0; attempt < 5; ++attempt) {  // best of 5: a VM may still lose cycles to its host
    std::uint64_t x = seed;
    const std::uint64_t m = factor;
    const double t0 = thread_cpu_seconds();
    for (std::int64_t i = 0; i < kIterations; ++i) {
      // Each multiply waits for the previous one. The empty asm after every multiply keeps the chain: with it only
      // after the block, GCC 11 at -O1 folded the eight multiplies into one by a hoisted m^8 and the clock came out
      // eight times too high.
      for (int u = 0; u < kUnroll; ++u) {
        x *= m;
        asm volatile("" : "+r"(x));
      }
    }
    const double s = thread_cpu_seconds() - t0;
    seed = x;
    if (s <= 0) continue;
    const double hz = kCyclesPerMul * kUnroll * static_cast<double>(kIterations) / s;
    if (hz > best) best = hz;
  }
  return best;
}

double rotation_flops_per_cycle(int lanes, bool fma, int fma_ports, bool separate_add_pipes) {
  const double ops_on_mul_pipes = fma ? 4.0 : separate_add_pipes ? 4.0 : 6.0;
  return lanes * 6.0 * fma_ports / ops_on_mul_pipes;
}

CpuInfo detect_cpu(bool calibrate) {
  CpuInfo info;
  info.model = read_key("/proc/cpuinfo", "model name", ':');
  if (info.model.empty()) info.model = read_key("/proc/cpuinfo", "Model", ':');
  if (info.model.empty()) info.model = "unknown CPU";
  info.threads = omp_get_max_threads();
  info.vendor = read_key("/proc/cpuinfo", "vendor_id", ':');
  info.separate_add_pipes = info.vendor == "AuthenticAMD" || info.vendor == "HygonGenuine";
  if (calibrate) info.clock_hz = calibrate_clock_hz();
  try {
    info.arm = detect_arm_cpu("/", "/", info.clock_hz);
  } catch (const std::exception&) {
    info.arm.reset();  // no readable /proc/cpuinfo: the generic description above stands
  }
  if (info.arm) {
    // ARM kernels print "ARMv8 Processor rev N" or nothing as the model: the core types say what it is.
    info.model = (info.arm->board.empty() ? std::string() : info.arm->board + ": ") + info.arm->summary();
    if (info.arm->clusters.front().type) info.vendor = info.arm->clusters.front().type->vendor;
  }
  use_simd_target(info, best_simd_target());
  return info;
}

void use_simd_target(CpuInfo& info, const SimdTarget& target) {
  info.simd = target;
  info.fma_ports = 2;
  // Zen 4 (family 25) double-pumps 512-bit ops on 256-bit pipes; Zen 5 (family 26) has full-width pipes.
  if (info.vendor == "AuthenticAMD" && info.simd.isa == Isa::Avx512 &&
      read_key("/proc/cpuinfo", "cpu family", ':') == "25")
    info.fma_ports = 1;
  info.flops_per_cycle =
      rotation_flops_per_cycle(info.simd.lanes, info.simd.fma, info.fma_ports, info.separate_add_pipes);
  info.peak_flops = info.threads * info.clock_hz * info.flops_per_cycle;
  if (!info.arm || info.arm->cores() == 0) return;
  // ARM: each cluster at its own clock and FMA width. With fewer threads than cores the sum is scaled by the share
  // of cores in use (which cores the OS picks is not known). A cluster of an unknown core keeps the generic model.
  double per_cycle_ghz = 0;  // sum of cores * flops per cycle * GHz
  int widest = 0;
  for (const ArmCluster& c : info.arm->clusters) {
    const int units = c.type ? c.type->fma_units : 2;
    widest = std::max(widest, units);
    const double ghz = c.clock_ghz > 0 ? c.clock_ghz : info.clock_hz / 1e9;
    per_cycle_ghz +=
        c.cores * ghz * rotation_flops_per_cycle(info.simd.lanes, info.simd.fma, units, info.separate_add_pipes);
  }
  const double used = std::min(1.0, static_cast<double>(info.threads) / info.arm->cores());
  info.fma_ports = widest;
  info.peak_flops = used * per_cycle_ghz * 1e9;
  // The per-core figure shown beside it: the peak's average per core and measured cycle.
  if (info.clock_hz > 0 && info.threads > 0) info.flops_per_cycle = info.peak_flops / (info.threads * info.clock_hz);
}

std::string os_name() {
  const std::string name = read_key("/etc/os-release", "PRETTY_NAME", '=');
  return name.empty() ? "unknown OS" : name;
}

}  // namespace bs::kernels
