// SPDX-License-Identifier: GPL-3.0-or-later
// AVX-512 row kernel of the fused demosaic + reprojection: 16 output pixels per step, integer arithmetic only.
//
// Why it is fast: bilinear demosaicing and bilinear interpolation are both linear, so one output pixel is a fixed
// weighted sum of the 4x4 mosaic window around its taps. Red and blue are a separable tent filter on their
// (zero-filled) planes, so their weights factor into an x part and a y part that do not depend on where the
// colours sit: per window row, vpmaddubsw forms both column-pair sums (cols 0/2 with weights 32-fx, 32+fx and
// cols 1/3 with 64-fx, fx, in 1/64), then vpmaddwd combines rows 0/2 or 1/3 the same way; the Bayer phase only
// selects which of the four results is blue and which is red. Green is interpolated from the four taps, two of
// which are green sites (4x the sample) and two not (sum of the 4 neighbours), chosen by one mask bit.
// All three channels end at 4096 x the value, rounded once: the result equals the scalar path bit for bit.
//
// The 4x4 windows come from a tile (rows loaded whole, bytes picked by vpermb) when a block's 16 windows lie
// close together, which is nearly always, else from 4 gathers (see fused_kernels.h).
//
// Only this function is compiled for AVX-512 (target attribute), so no AVX-512 code leaks into inline functions
// shared with the rest of the program; fused.cpp calls it only when the CPU supports it.
#include "vision/reproject/fused_kernels.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define BS_FUSED_X86 1
// GCC 12's AVX-512 headers initialise their "undefined" placeholder vectors from themselves (__Y = __Y), which
// -Wuninitialized reports once the intrinsics are inlined here; the values are never read.
#if !defined(__clang__)  // clang has neither the warning nor the problem
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#endif

namespace bs::vision::detail {

#if BS_FUSED_X86

#define BS_AVX512_TARGET __attribute__((target("avx512f,avx512bw,avx512vbmi")))

// Each lane's 4 bytes of one tile row (a lambda would not inherit the target attribute).
BS_AVX512_TARGET __attribute__((always_inline)) inline __m512i pick_tile_row(const std::uint8_t* row, __mmask64 load,
                                                                             __m512i pick) {
  return _mm512_permutexvar_epi8(pick, _mm512_maskz_loadu_epi8(load, row));
}

bool fused_avx512_supported() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
         __builtin_cpu_supports("avx512vbmi");
}

BS_AVX512_TARGET void fused_row_avx512(const std::uint32_t* lut, const FusedBlock* blocks, int count,
                                       const std::uint8_t* mosaic, int width, int blue_col, int blue_row,
                                       std::uint8_t* out) {
  const __m512i one = _mm512_set1_epi32(1);
  const __m512i special = _mm512_set1_epi32(-1);
  const __m512i offset_bits = _mm512_set1_epi32((1 << kPackedOffsetBits) - 1);
  const __m512i five_bits = _mm512_set1_epi32(31);
  // The window starts one column/row before the taps: blue is in window cols 1/3 when (x0 - 1) has the other parity.
  const __m512i cols13_parity = _mm512_set1_epi32(blue_col ^ 1);
  const __m512i rows13_parity = _mm512_set1_epi32(blue_row ^ 1);
  const __m512i stride = _mm512_set1_epi32(width);
  const __m512 inv_width = _mm512_set1_ps(1.0f / static_cast<float>(width));
  const __m512i low_bytes = _mm512_set1_epi32(0x00FF00FF);
  const __m512i half = _mm512_set1_epi32(2048);
  const __mmask32 odd_words = 0xAAAAAAAAu;
  // Per dword: bytes (b0, b2, b1, b3) so vpmaddubsw pairs cols 0/2 and cols 1/3.
  const __m512i pair_cols = _mm512_broadcast_i32x4(_mm_setr_epi8(0, 2, 1, 3, 4, 6, 5, 7, 8, 10, 9, 11, 12, 14, 13, 15));
  // Output: B, G, R in the low three bytes of each dword -> 48 packed bytes.
  const __m512i pack_bytes =
      _mm512_broadcast_i32x4(_mm_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1));
  const __m512i pack_dwords = _mm512_setr_epi32(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 3, 7, 11, 15);

  const __m512i tile_bytes = _mm512_set1_epi32(0x03020100);
  const __m512i low_byte_x4 = _mm512_broadcast_i32x4(_mm_setr_epi8(0, 0, 0, 0, 4, 4, 4, 4, 8, 8, 8, 8, 12, 12, 12, 12));
  const __m512i six_bits = _mm512_set1_epi32(63);
  const __m512i seven = _mm512_set1_epi32(7);

  for (int x = 0; x < count; x += kBlockPixels, ++blocks) {
    const int n = count - x < kBlockPixels ? count - x : kBlockPixels;
    const __mmask16 lanes = static_cast<__mmask16>(n == 16 ? 0xFFFFu : (1u << n) - 1);
    const __m512i e = _mm512_maskz_loadu_epi32(lanes, lut + x);
    const __mmask16 valid = _mm512_mask_cmpneq_epi32_mask(lanes, e, special);
    const __m512i fx = _mm512_and_si512(_mm512_srli_epi32(e, 22), five_bits);
    const __m512i fy = _mm512_srli_epi32(e, 27);
    __m512i r0, r1, r2, r3, col_parity, row_parity;
    if (blocks->rows > 0) {
      // Tiled: load each tile row once, pick every lane's 4 bytes (tile column .. +3) with one permutation.
      const std::uint8_t* tile = mosaic + blocks->base;
      const __mmask64 load = blocks->bytes >= 64 ? ~__mmask64{0} : (__mmask64{1} << blocks->bytes) - 1;
      const __m512i column = _mm512_and_si512(e, six_bits);
      const __m512i pick = _mm512_add_epi32(tile_bytes, _mm512_shuffle_epi8(column, low_byte_x4));
      r0 = pick_tile_row(tile, load, pick);
      r1 = pick_tile_row(tile + width, load, pick);
      r2 = pick_tile_row(tile + 2 * width, load, pick);
      r3 = pick_tile_row(tile + 3 * width, load, pick);
      if (blocks->rows > 1) {
        // Windows starting d rows lower take tile rows d .. d + 3: a rolling set of four rows.
        const __m512i tile_y = _mm512_and_si512(_mm512_srli_epi32(e, 6), seven);
        __m512i t0 = r0, t1 = r1, t2 = r2, t3 = r3;
        for (int d = 1; d < blocks->rows; ++d) {
          t0 = t1;
          t1 = t2;
          t2 = t3;
          t3 = pick_tile_row(tile + static_cast<std::ptrdiff_t>(d + 3) * width, load, pick);
          const __mmask16 here = _mm512_cmpeq_epi32_mask(tile_y, _mm512_set1_epi32(d));
          r0 = _mm512_mask_blend_epi32(here, r0, t0);
          r1 = _mm512_mask_blend_epi32(here, r1, t1);
          r2 = _mm512_mask_blend_epi32(here, r2, t2);
          r3 = _mm512_mask_blend_epi32(here, r3, t3);
        }
      }
      col_parity = _mm512_srli_epi32(e, 9);
      row_parity = _mm512_srli_epi32(e, 10);
    } else {
      const __m512i offset = _mm512_and_si512(e, offset_bits);
      // The width is even, so the offset's parity is the column's.
      col_parity = offset;
      row_parity = _mm512_cvttps_epi32(
          _mm512_mul_ps(_mm512_add_ps(_mm512_cvtepi32_ps(offset), _mm512_set1_ps(0.5f)), inv_width));
      // The 4x4 window, one dword (4 bytes) per row.
      const __m512i zero = _mm512_setzero_si512();
      __m512i index = offset;
      r0 = _mm512_mask_i32gather_epi32(zero, valid, index, mosaic, 1);
      index = _mm512_add_epi32(index, stride);
      r1 = _mm512_mask_i32gather_epi32(zero, valid, index, mosaic, 1);
      index = _mm512_add_epi32(index, stride);
      r2 = _mm512_mask_i32gather_epi32(zero, valid, index, mosaic, 1);
      index = _mm512_add_epi32(index, stride);
      r3 = _mm512_mask_i32gather_epi32(zero, valid, index, mosaic, 1);
    }
    const __mmask16 blue_cols13 = _mm512_cmpeq_epi32_mask(_mm512_and_si512(col_parity, one), cols13_parity);
    const __mmask16 blue_rows13 = _mm512_cmpeq_epi32_mask(_mm512_and_si512(row_parity, one), rows13_parity);
    const __mmask16 green_at_tap00 = _kxor_mask16(blue_cols13, blue_rows13);

    // Weights. fy * 65535 = (fy << 16) - fy turns a constant word pair (a, b) into (a - fy, b + fy).
    const __m512i fx_pair = _mm512_sub_epi32(_mm512_slli_epi32(fx, 16), fx);
    const __m512i fy_pair = _mm512_sub_epi32(_mm512_slli_epi32(fy, 16), fy);
    // Bytes (32 - fx, 32 + fx, 64 - fx, fx) = 0x00402020 + fx * 0x00FF00FF.
    const __m512i fx255 = _mm512_sub_epi32(_mm512_slli_epi32(fx, 8), fx);
    const __m512i w_cols =
        _mm512_add_epi32(_mm512_set1_epi32(0x00402020), _mm512_add_epi32(fx255, _mm512_slli_epi32(fx255, 16)));
    const __m512i w_rows13 = _mm512_add_epi32(_mm512_set1_epi32(64), fy_pair);          // (64 - fy, fy)
    const __m512i w_rows02 = _mm512_add_epi32(_mm512_set1_epi32(0x00200020), fy_pair);  // (32 - fy, 32 + fy)
    const __m512i w_green_x = _mm512_add_epi32(_mm512_set1_epi32(32), fx_pair);         // (32 - fx, fx)
    const __m512i w_green_y = _mm512_add_epi32(_mm512_set1_epi32(32), fy_pair);         // (32 - fy, fy)

    // Red and blue: per row, word 0 = cols 0/2, word 1 = cols 1/3 (x weights, 1/64).
    const __m512i p0 = _mm512_maddubs_epi16(_mm512_shuffle_epi8(r0, pair_cols), w_cols);
    const __m512i p1 = _mm512_maddubs_epi16(_mm512_shuffle_epi8(r1, pair_cols), w_cols);
    const __m512i p2 = _mm512_maddubs_epi16(_mm512_shuffle_epi8(r2, pair_cols), w_cols);
    const __m512i p3 = _mm512_maddubs_epi16(_mm512_shuffle_epi8(r3, pair_cols), w_cols);
    // Pair rows 1/3 and 0/2 word by word, then the y weights: 4096 x the value.
    const __m512i c02_r13 =
        _mm512_madd_epi16(_mm512_mask_blend_epi16(odd_words, p1, _mm512_slli_epi32(p3, 16)), w_rows13);
    const __m512i c13_r13 =
        _mm512_madd_epi16(_mm512_mask_blend_epi16(odd_words, _mm512_srli_epi32(p1, 16), p3), w_rows13);
    const __m512i c02_r02 =
        _mm512_madd_epi16(_mm512_mask_blend_epi16(odd_words, p0, _mm512_slli_epi32(p2, 16)), w_rows02);
    const __m512i c13_r02 =
        _mm512_madd_epi16(_mm512_mask_blend_epi16(odd_words, _mm512_srli_epi32(p0, 16), p2), w_rows02);
    const __m512i blue_r13 = _mm512_mask_blend_epi32(blue_cols13, c02_r13, c13_r13);
    const __m512i red_r13 = _mm512_mask_blend_epi32(blue_cols13, c13_r13, c02_r13);
    const __m512i blue_r02 = _mm512_mask_blend_epi32(blue_cols13, c02_r02, c13_r02);
    const __m512i red_r02 = _mm512_mask_blend_epi32(blue_cols13, c13_r02, c02_r02);
    const __m512i blue = _mm512_mask_blend_epi32(blue_rows13, blue_r02, blue_r13);
    const __m512i red = _mm512_mask_blend_epi32(blue_rows13, red_r13, red_r02);

    // Green: even/odd columns of each row as word pairs, E = (b0, b2), O = (b1, b3).
    const __m512i e0 = _mm512_and_si512(r0, low_bytes), o0 = _mm512_and_si512(_mm512_srli_epi32(r0, 8), low_bytes);
    const __m512i e1 = _mm512_and_si512(r1, low_bytes), o1 = _mm512_and_si512(_mm512_srli_epi32(r1, 8), low_bytes);
    const __m512i e2 = _mm512_and_si512(r2, low_bytes), o2 = _mm512_and_si512(_mm512_srli_epi32(r2, 8), low_bytes);
    const __m512i e3 = _mm512_and_si512(r3, low_bytes), o3 = _mm512_and_si512(_mm512_srli_epi32(r3, 8), low_bytes);
    // Taps t00 = W11, t01 = W12, t10 = W21, t11 = W22 as (left, right) word pairs, each 4x its green value.
    // Word sums stay below 1024, so adding whole dwords never carries between the two words.
    // Tap t00 not green: (X00, 4 W12) and (4 W21, X11), X = sum of the 4 neighbours.
    const __m512i top_n = _mm512_mask_blend_epi16(
        odd_words, _mm512_add_epi32(_mm512_add_epi32(o0, o2), _mm512_add_epi32(e1, _mm512_srli_epi32(e1, 16))),
        _mm512_slli_epi32(e1, 2));
    const __m512i bottom_n = _mm512_mask_blend_epi16(
        odd_words, _mm512_slli_epi32(o2, 2),
        _mm512_add_epi32(_mm512_add_epi32(e1, e3), _mm512_add_epi32(o2, _mm512_slli_epi32(o2, 16))));
    // Tap t00 green: (4 W11, X01) and (X10, 4 W22).
    const __m512i top_g = _mm512_mask_blend_epi16(
        odd_words, _mm512_slli_epi32(o1, 2),
        _mm512_add_epi32(_mm512_add_epi32(e0, e2), _mm512_add_epi32(o1, _mm512_slli_epi32(o1, 16))));
    const __m512i bottom_g = _mm512_mask_blend_epi16(
        odd_words, _mm512_add_epi32(_mm512_add_epi32(o1, o3), _mm512_add_epi32(e2, _mm512_srli_epi32(e2, 16))),
        _mm512_slli_epi32(e2, 2));
    const __m512i top = _mm512_madd_epi16(_mm512_mask_blend_epi32(green_at_tap00, top_n, top_g), w_green_x);
    const __m512i bottom = _mm512_madd_epi16(_mm512_mask_blend_epi32(green_at_tap00, bottom_n, bottom_g), w_green_x);
    const __m512i green =
        _mm512_madd_epi16(_mm512_mask_blend_epi16(odd_words, top, _mm512_slli_epi32(bottom, 16)), w_green_y);

    // Round once (/4096), pack B, G, R into 3 bytes per pixel and store 3n bytes.
    const __m512i b8 = _mm512_srli_epi32(_mm512_add_epi32(blue, half), 12);
    const __m512i g8 = _mm512_srli_epi32(_mm512_add_epi32(green, half), 12);
    const __m512i r8 = _mm512_srli_epi32(_mm512_add_epi32(red, half), 12);
    const __m512i bgr = _mm512_or_si512(b8, _mm512_or_si512(_mm512_slli_epi32(g8, 8), _mm512_slli_epi32(r8, 16)));
    const __m512i packed = _mm512_permutexvar_epi32(pack_dwords, _mm512_shuffle_epi8(bgr, pack_bytes));
    const __mmask64 bytes = n == 16 ? 0xFFFFFFFFFFFFull : (std::uint64_t{1} << (3 * n)) - 1;
    _mm512_mask_storeu_epi8(out + 3 * x, bytes, packed);
  }
}

#else

bool fused_avx512_supported() { return false; }

void fused_row_avx512(const std::uint32_t*, const FusedBlock*, int, const std::uint8_t*, int, int, int, std::uint8_t*) {
}

#endif

}  // namespace bs::vision::detail
