// SPDX-License-Identifier: GPL-3.0-or-later
// The rotation step's three vector operations for one instruction set, written as that ISA's instructions so the
// compiler cannot choose the contraction itself. With plain vector arithmetic GCC 12 fused "c*x - s*y" as
// fnmadd(s, y, c*x) and then needed a register copy per chain and step (8-12 extra vmovaps per step with AVX-512).
// AVX-512 and AVX2+FMA use intrinsics (always inlined, never emitted out of line, so nothing compiled for one ISA
// can be linked into another's path); SSE4.1 (no FMA: mul + sub/add) and the generic 128-bit code (NEON on ARM,
// where -ffp-contract=fast gives fmla) use vector arithmetic. Included inside namespace BS_SIMD_NS.
// Requires the typedef vf (BS_SIMD_BYTES-wide float vector) to be declared before inclusion, <cstdint>, and
// <immintrin.h> included at global scope on x86.
#if BS_SIMD_BYTES == 64 && defined(__AVX512F__)
#define BS_HAS_FMA 1
inline vf vmul(vf a, vf b) { return _mm512_mul_ps(a, b); }
inline vf vfma(vf a, vf b, vf c) { return _mm512_fmadd_ps(a, b, c); }  // a*b + c
inline vf vfms(vf a, vf b, vf c) { return _mm512_fmsub_ps(a, b, c); }  // a*b - c
#elif BS_SIMD_BYTES == 32 && defined(__FMA__)
#define BS_HAS_FMA 1
inline vf vmul(vf a, vf b) { return _mm256_mul_ps(a, b); }
inline vf vfma(vf a, vf b, vf c) { return _mm256_fmadd_ps(a, b, c); }
inline vf vfms(vf a, vf b, vf c) { return _mm256_fmsub_ps(a, b, c); }
#else
#if defined(__ARM_NEON) || defined(__FMA__)
#define BS_HAS_FMA 1
#else
#define BS_HAS_FMA 0
#endif
inline vf vmul(vf a, vf b) { return a * b; }
inline vf vfma(vf a, vf b, vf c) { return a * b + c; }
inline vf vfms(vf a, vf b, vf c) { return a * b - c; }
#endif

// `steps` rotations of the K chains in x and y: per chain and step t = s*y, u = s*x, x = c*x - t, y = c*y + u, each
// written in place (no register copies). Written once for the kernel (rotation_simd_impl.h) and its empirical
// ceiling (ceiling_simd_impl.h), so that the ceiling times exactly the kernel's instruction mix. Always inlined: the
// chains stay in the caller's registers, and nothing of one ISA is emitted out of line for the linker to share.
template <int K>
inline __attribute__((always_inline)) void rotate_steps(vf (&x)[K], vf (&y)[K], std::int64_t steps, vf vc, vf vs) {
  for (std::int64_t n = 0; n < steps; ++n) {
#pragma GCC unroll 16
    for (int k = 0; k < K; ++k) {
      const vf t = vmul(vs, y[k]), u = vmul(vs, x[k]);
      x[k] = vfms(vc, x[k], t);
      y[k] = vfma(vc, y[k], u);
    }
  }
}
