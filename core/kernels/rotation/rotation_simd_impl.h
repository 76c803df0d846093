// SPDX-License-Identifier: GPL-3.0-or-later
// Included by one translation unit per instruction set (rotation_simd_<isa>.cpp), each compiled with its own
// -m flags and -ffp-contract=fast so the generic vector code below becomes that ISA's mul + FMA. Everything here
// lives in the per-ISA namespace BS_SIMD_NS and uses no inline library templates: a shared inline function
// compiled for AVX-512 could otherwise be picked by the linker for a machine without it.
// Requires: BS_SIMD_NS (namespace name), BS_SIMD_BYTES (vector width in bytes), BS_SIMD_CHAINS (chains per block).
#include <cstdint>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>  // the AVX2/AVX-512 operations of simd_ops_impl.h
#endif

namespace bs::kernels::BS_SIMD_NS {

constexpr int kLanes = BS_SIMD_BYTES / 4;
typedef float vf __attribute__((vector_size(BS_SIMD_BYTES), aligned(BS_SIMD_BYTES)));
typedef float v4 __attribute__((vector_size(16), aligned(16)));
#include "kernels/simd_ops_impl.h"

// Independent vector chains per block (BS_SIMD_CHAINS, set per ISA file). A step of one chain is mul -> FMA
// (7-8 cycles of latency on current x86 cores) while two FMA pipes retire a chain's 4 operations in 2 cycles, so
// >= 4 chains keep both pipes busy. The upper bound is the register file: each chain holds x and y, plus the two
// constants and two temporaries. With 16 vector registers (AVX2, SSE4.1) that is 6 chains: the former 8 made GCC
// keep 4 of the 16 state vectors on the stack, a load and a store per chain and step (about 5 % fewer flops per
// CPU-second on a Zen 3 EPYC). AVX-512 and NEON have 32 registers.
constexpr int kChains = BS_SIMD_CHAINS;

int lanes() { return kLanes; }
int chains() { return kChains; }

// `steps` rotations of the K chains at px/py, held in registers throughout (rotate_steps, simd_ops_impl.h): two
// multiplies and two fused ops per chain and step.
template <int K>
void rotate_block(vf* px, vf* py, std::int64_t steps, vf vc, vf vs) {
  vf x[K], y[K];
#pragma GCC unroll 16
  for (int k = 0; k < K; ++k) x[k] = px[k], y[k] = py[k];
  rotate_steps(x, y, steps, vc, vs);
#pragma GCC unroll 16
  for (int k = 0; k < K; ++k) px[k] = x[k], py[k] = y[k];
}

// Throughput variant: all points packed kLanes to a vector, kChains vectors per block, blocks across threads.
// `nvec` is a multiple of kChains; xs/ys are BS_SIMD_BYTES-aligned. The whole point is ONE parallel region: a
// barrier per chunk of steps made the threads spin-wait for each other, and on a shared machine (a descheduled
// thread) that cost up to 3/4 of the throughput. Blocks go to threads one at a time (dynamic), so a thread that
// runs takes the blocks of one that does not. Each block runs all `steps` in sub-chunks of ~4e6 point-steps
// (<= 40 ms on any core doing >= 0.6 GFLOPS), asking `cancelled(token)` between them; returns false when cancelled
// (the state is then partly advanced and must be discarded).
bool advance_throughput(float* xs, float* ys, std::int64_t nvec, std::int64_t steps, float c, float s,
                        bool (*cancelled)(const void*), const void* token) {
  const std::int64_t blocks = nvec / kChains;
  const std::int64_t sub_chunk = (std::int64_t{1} << 22) / (kChains * kLanes);
  int stopped = 0;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t b = 0; b < blocks; ++b) {
    vf* px = reinterpret_cast<vf*>(xs) + b * kChains;
    vf* py = reinterpret_cast<vf*>(ys) + b * kChains;
    const vf vc = vf{} + c, vs = vf{} + s;
    std::int64_t done = 0;
    while (done < steps && !__atomic_load_n(&stopped, __ATOMIC_RELAXED)) {
      if (cancelled && cancelled(token)) {
        __atomic_store_n(&stopped, 1, __ATOMIC_RELAXED);
        break;
      }
      const std::int64_t n = steps - done < sub_chunk ? steps - done : sub_chunk;
      rotate_block<kChains>(px, py, n, vc, vs);
      done += n;
    }
  }
  return !stopped;
}

// Paper variant: one OpenMP task per worker, as in the paper; a worker's D points sit in 4-wide vectors
// (stride = D rounded up to 4), so small D gives one latency-bound dependent chain per task.
void advance_paper(float* xs, float* ys, std::int64_t workers, int stride, std::int64_t steps, float c, float s) {
#pragma omp parallel
#pragma omp single
  for (std::int64_t w = 0; w < workers; ++w) {
#pragma omp task firstprivate(w)
    {
      const v4 vc = v4{} + c, vs = v4{} + s;
      for (int g = 0; g < stride; g += 4) {
        v4* px = reinterpret_cast<v4*>(xs + w * stride + g);
        v4* py = reinterpret_cast<v4*>(ys + w * stride + g);
        v4 x = *px, y = *py;
        for (std::int64_t n = 0; n < steps; ++n) {
          const v4 nx = vc * x - vs * y;
          y = vs * x + vc * y;
          x = nx;
        }
        *px = x;
        *py = y;
      }
    }
  }
}

}  // namespace bs::kernels::BS_SIMD_NS
