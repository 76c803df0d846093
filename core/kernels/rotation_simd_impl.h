// SPDX-License-Identifier: GPL-3.0-or-later
// Included by one translation unit per instruction set (rotation_simd_<isa>.cpp), each compiled with its own
// -m flags and -ffp-contract=fast so the generic vector code below becomes that ISA's mul + FMA. Everything here
// lives in the per-ISA namespace BS_SIMD_NS and uses no inline library templates: a shared inline function
// compiled for AVX-512 could otherwise be picked by the linker for a machine without it.
// Requires: BS_SIMD_NS (namespace name) and BS_SIMD_BYTES (vector width in bytes).
#include <cstdint>

namespace bs::kernels::BS_SIMD_NS {

constexpr int kLanes = BS_SIMD_BYTES / 4;
// Independent vector chains per block: a rotation step is mul -> FMA (8 cycles of latency on current x86 cores)
// and two FMA ports retire two per cycle, so >= 4 chains (x and y each) keep both ports busy; 8 measured best.
constexpr int kChains = 8;  // the loop below is written out for exactly 8 (BS_CHAINS)
typedef float vf __attribute__((vector_size(BS_SIMD_BYTES), aligned(BS_SIMD_BYTES)));
typedef float v4 __attribute__((vector_size(16), aligned(16)));

int lanes() { return kLanes; }
int chains() { return kChains; }

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
    // Named registers, not arrays: GCC keeps arrays of vectors on the stack, and the store/reload per step
    // would add latency to every chain.
#define BS_CHAINS(X) X(0) X(1) X(2) X(3) X(4) X(5) X(6) X(7)
#define BS_LOAD(k) vf x##k = px[k], y##k = py[k];
#define BS_STEP(k)                             \
  {                                            \
    const vf nx = vc * x##k - vs * y##k;       \
    y##k = vs * x##k + vc * y##k;              \
    x##k = nx;                                 \
  }
#define BS_STORE(k) px[k] = x##k, py[k] = y##k;
    BS_CHAINS(BS_LOAD)
    const vf vc = vf{} + c, vs = vf{} + s;
    std::int64_t done = 0;
    while (done < steps && !__atomic_load_n(&stopped, __ATOMIC_RELAXED)) {
      if (cancelled && cancelled(token)) {
        __atomic_store_n(&stopped, 1, __ATOMIC_RELAXED);
        break;
      }
      const std::int64_t n_end = steps - done < sub_chunk ? steps - done : sub_chunk;
      for (std::int64_t n = 0; n < n_end; ++n) {
        BS_CHAINS(BS_STEP)
      }
      done += n_end;
    }
    BS_CHAINS(BS_STORE)
#undef BS_STORE
#undef BS_STEP
#undef BS_LOAD
#undef BS_CHAINS
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
