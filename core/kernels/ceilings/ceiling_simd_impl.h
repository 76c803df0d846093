// SPDX-License-Identifier: GPL-3.0-or-later
// Empirical-ceiling micro-kernels for one instruction set (ceiling_simd_<isa>.cpp, compiled with that ISA's -m
// flags like rotation_simd_<isa>.cpp). They run on ONE thread over state the caller passes in: initial values the
// compiler cannot see, so identical chains cannot be merged (with constant starting points GCC folded six chains
// into one), and final values written back, so the work cannot be dropped and a test can check the step count.
// Requires: BS_SIMD_NS, BS_SIMD_BYTES. No library templates (see rotation_simd_impl.h).
#include <cstdint>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>  // the AVX2/AVX-512 operations of simd_ops_impl.h
#endif

namespace bs::kernels::BS_SIMD_NS::ceiling {

typedef float vf __attribute__((vector_size(BS_SIMD_BYTES), aligned(BS_SIMD_BYTES)));
#include "kernels/simd_ops_impl.h"

constexpr int kLanes = BS_SIMD_BYTES / 4;
// FMA accumulators: FMA latency 4-5 cycles x 2 pipes needs >= 10 independent ones; 12 (16 registers) or 24
// (32 registers) leave room for the two constants.
#if BS_SIMD_BYTES == 64 || defined(__aarch64__)
constexpr int kFmaChains = 24;
#else
constexpr int kFmaChains = 12;
#endif

int lanes() { return kLanes; }
int fma_chains() { return BS_HAS_FMA ? kFmaChains : 0; }

// The rotation kernel's own instruction mix (2 mul + FMS + FMA per vector and step) on K independent chains held
// in registers: no loads, no stores, no scheduling, no cancellation checks. 6 counted flops per lane and step.
template <int K>
void mix(float* xs, float* ys, std::int64_t steps, float c, float s) {
  vf x[K], y[K];
  const vf vc = vf{} + c, vs = vf{} + s;
#pragma GCC unroll 16
  for (int k = 0; k < K; ++k)
    __builtin_memcpy(&x[k], xs + k * kLanes, sizeof(vf)), __builtin_memcpy(&y[k], ys + k * kLanes, sizeof(vf));
  rotate_steps(x, y, steps, vc, vs);
#pragma GCC unroll 16
  for (int k = 0; k < K; ++k)
    __builtin_memcpy(xs + k * kLanes, &x[k], sizeof(vf)), __builtin_memcpy(ys + k * kLanes, &y[k], sizeof(vf));
}

// mix<K> for the K of `Ks` that equals `chains`; false when none does. The chain counts are compile-time (the
// chains live in registers), so each one the caller may ask for is instantiated here, listed once.
template <int... Ks>
bool mix_for(int chains, float* xs, float* ys, std::int64_t steps, float c, float s) {
  return ((chains == Ks && (mix<Ks>(xs, ys, steps, c, s), true)) || ...);
}

// K chains: one of 2, 4, 5, 6, 8, 10, 12 (false otherwise). xs/ys hold K * lanes() floats each.
bool rotation_mix(int chains, float* xs, float* ys, std::int64_t steps, float c, float s) {
  return mix_for<2, 4, 5, 6, 8, 10, 12>(chains, xs, ys, steps, c, s);
}

// Plain FMA throughput: acc = acc * a + b on fma_chains() independent accumulators (acc holds that many vectors).
// 2 counted flops per lane and FMA. With |a| < 1 every accumulator converges to b / (1 - a) and stays finite.
// Returns false when this ISA has no FMA (SSE4.1, generic x86): the figure is then not measured.
bool fma(float* acc, std::int64_t steps, float a, float b) {
#if BS_HAS_FMA
  vf r[kFmaChains];
  const vf va = vf{} + a, vb = vf{} + b;
#pragma GCC unroll 32
  for (int k = 0; k < kFmaChains; ++k) __builtin_memcpy(&r[k], acc + k * kLanes, sizeof(vf));
  for (std::int64_t n = 0; n < steps; ++n) {
#pragma GCC unroll 32
    for (int k = 0; k < kFmaChains; ++k) r[k] = vfma(r[k], va, vb);
  }
#pragma GCC unroll 32
  for (int k = 0; k < kFmaChains; ++k) __builtin_memcpy(acc + k * kLanes, &r[k], sizeof(vf));
  return true;
#else
  (void)acc, (void)steps, (void)a, (void)b;
  return false;
#endif
}

}  // namespace bs::kernels::BS_SIMD_NS::ceiling
