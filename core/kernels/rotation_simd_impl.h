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
// and two FMA ports retire two per cycle, so >= 4 chains (x and y each) keep both ports busy.
constexpr int kChains = 4;  // the loop below is written out for exactly 4
typedef float vf __attribute__((vector_size(BS_SIMD_BYTES), aligned(BS_SIMD_BYTES)));
typedef float v4 __attribute__((vector_size(16), aligned(16)));

int lanes() { return kLanes; }
int chains() { return kChains; }

// Throughput variant: all points packed kLanes to a vector, kChains vectors per block, blocks across threads.
// `nvec` is a multiple of kChains; xs/ys are BS_SIMD_BYTES-aligned.
void advance_throughput(float* xs, float* ys, std::int64_t nvec, std::int64_t steps, float c, float s) {
  const std::int64_t blocks = nvec / kChains;
#pragma omp parallel for schedule(static)
  for (std::int64_t b = 0; b < blocks; ++b) {
    vf* px = reinterpret_cast<vf*>(xs) + b * kChains;
    vf* py = reinterpret_cast<vf*>(ys) + b * kChains;
    // Named registers, not arrays: GCC keeps arrays of vectors on the stack, and the store/reload per step
    // would add latency to every chain.
    vf x0 = px[0], x1 = px[1], x2 = px[2], x3 = px[3];
    vf y0 = py[0], y1 = py[1], y2 = py[2], y3 = py[3];
    const vf vc = vf{} + c, vs = vf{} + s;
    for (std::int64_t n = 0; n < steps; ++n) {
      const vf n0 = vc * x0 - vs * y0, n1 = vc * x1 - vs * y1, n2 = vc * x2 - vs * y2, n3 = vc * x3 - vs * y3;
      y0 = vs * x0 + vc * y0;
      y1 = vs * x1 + vc * y1;
      y2 = vs * x2 + vc * y2;
      y3 = vs * x3 + vc * y3;
      x0 = n0;
      x1 = n1;
      x2 = n2;
      x3 = n3;
    }
    px[0] = x0, px[1] = x1, px[2] = x2, px[3] = x3;
    py[0] = y0, py[1] = y1, py[2] = y2, py[3] = y3;
  }
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
