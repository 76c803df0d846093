// SPDX-License-Identifier: GPL-3.0-or-later
// Highway compiles this file once per instruction set (foreach_target.h re-includes it); HWY_DYNAMIC_DISPATCH
// picks the best one the CPU has at run time, so one binary runs AVX-512 where it exists and SSE4 where not, and
// the same source builds NEON on an ARM robot computer.
//
// Why the vector code is bit-exact with the scalar definition (bayer_pixel.h): it evaluates the same integer
// expressions in lanes wide enough that nothing overflows (int16 for 8-bit mosaics: the largest MHC magnitude is
// 28 * 255 + 8 = 7148; int32 for 16-bit: 28 * 65535 + 8), shifts right arithmetically as C++20's >> does on
// negative ints, and clamps by the saturating narrowing (DemoteTo) to [0, 255] or [0, 65535], as std::clamp does.
//
// Why it is fast: a row alternates two site kinds (green and one of red/blue). Rather than split the row into
// even and odd columns, every lane computes both kinds' formulas from unaligned loads at the neighbouring
// columns, and a fixed even/odd lane mask picks per lane: about twice the arithmetic of a split, but no shuffles
// before the one interleaving store (StoreInterleaved3) that writes BGR.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "vision/bayer_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>

#include "vision/bayer.h"
#include "vision/bayer_pixel.h"
#include "vision/bayer_simd.h"

#ifndef BS_BAYER_SIMD_JOB
#define BS_BAYER_SIMD_JOB
namespace bs::vision::detail {
// One call's inputs, shared by every instruction set's copy of the kernel.
struct DemosaicJob {
  const cv::Mat* raw;
  cv::Mat* out;
  BayerPattern pattern;
  bool mhc;
};
}  // namespace bs::vision::detail
#endif

HWY_BEFORE_NAMESPACE();
namespace bs::vision::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The mosaic at `p`, widened to the signed working lane type.
template <class DW, class DT, class T>
HWY_INLINE hn::Vec<DW> load_wide(DW dw, DT dt, const T* p) {
  return hn::PromoteTo(dw, hn::LoadU(dt, p));
}

// (a + b + c + d + 2) >> 2 in the sample type, without widening: from the rounded pair means ab = (a + b + 1) >> 1
// and cd, it is (ab + cd + 1) >> 1 when both pair sums are even, else (ab + cd) >> 1, i.e. one less when ab + cd
// is odd. (With s1 = a + b, s2 = c + d: 2 ab + 2 cd = s1 + s2 + odd1 + odd2, so (s1 + s2 + 2) / 4 =
// (ab + cd + 1 - (odd1 + odd2) / 2) / 2, floored.)
template <class D, class V>
HWY_INLINE V mean4_rounded(D d, V ab, V cd, V a, V b, V c, V e) {
  const V odd_pair = hn::Or(hn::Xor(a, b), hn::Xor(c, e));
  const V correction = hn::And(hn::And(odd_pair, hn::Xor(ab, cd)), hn::Set(d, 1));
  return hn::Sub(hn::AverageRound(ab, cd), correction);
}

// Bilinear: Lanes(d) pixels of one row from column c on (`green` marks the lanes on green sites), computed in
// the sample type itself (AverageRound is (a + b + 1) >> 1 exactly), so a vector holds as many pixels as fit.
// `x` is the colour (0 B or 2 R) of the row's other sites, `2 - x` the
// one measured only in the rows above and below. Writes BGR to dst + 3 c.
template <class D, class M, class T>
HWY_INLINE void bilinear_vector(D d, const T* const row[5], int c, M green, int x, T* dst) {
  using V = hn::Vec<D>;
  const T* const r0 = row[2] + c;
  const T* const up = row[1] + c;
  const T* const down = row[3] + c;
  const V v = hn::LoadU(d, r0), w = hn::LoadU(d, r0 - 1), e = hn::LoadU(d, r0 + 1);
  const V n = hn::LoadU(d, up), s = hn::LoadU(d, down);
  const V nw = hn::LoadU(d, up - 1), ne = hn::LoadU(d, up + 1), sw = hn::LoadU(d, down - 1), se = hn::LoadU(d, down + 1);
  const V we = hn::AverageRound(w, e), ns = hn::AverageRound(n, s);    // at green sites: x and 2 - x
  const V cross = mean4_rounded(d, we, ns, w, e, n, s);                 // at x sites: green
  const V top = hn::AverageRound(nw, ne), bottom = hn::AverageRound(sw, se);
  const V diagonal = mean4_rounded(d, top, bottom, nw, ne, sw, se);     // at x sites: 2 - x
  const V ch_g = hn::IfThenElse(green, v, cross);
  const V ch_x = hn::IfThenElse(green, we, v);
  const V ch_y = hn::IfThenElse(green, ns, diagonal);
  T* const out = dst + 3 * c;
  if (x == 0) hn::StoreInterleaved3(ch_x, ch_g, ch_y, d, out);
  else hn::StoreInterleaved3(ch_y, ch_g, ch_x, d, out);
}

// Malvar-He-Cutler: Lanes(dw) pixels of one row from column c on, as bilinear_vector but in the wider signed
// type dw, the kernels having negative weights.
template <class DW, class DT, class M, class T>
HWY_INLINE void mhc_vector(DW dw, DT dt, const T* const row[5], int c, M green, int x, T* dst) {
  using V = hn::Vec<DW>;
  const T* const r0 = row[2] + c;
  const V v = load_wide(dw, dt, r0);
  const V w = load_wide(dw, dt, r0 - 1), e = load_wide(dw, dt, r0 + 1);
  const V n = load_wide(dw, dt, row[1] + c), s = load_wide(dw, dt, row[3] + c);
  const V we = hn::Add(w, e), ns = hn::Add(n, s);
  const V d = hn::Add(hn::Add(load_wide(dw, dt, row[1] + c - 1), load_wide(dw, dt, row[1] + c + 1)),
                      hn::Add(load_wide(dw, dt, row[3] + c - 1), load_wide(dw, dt, row[3] + c + 1)));
  const V n2 = hn::Add(load_wide(dw, dt, row[0] + c), load_wide(dw, dt, row[4] + c));
  const V w2 = hn::Add(load_wide(dw, dt, r0 - 2), load_wide(dw, dt, r0 + 2));
  // Constant multiples as shifts and adds: 32-bit multiplies are slow on x86 and the sums are the same.
  const V v2 = hn::ShiftLeft<1>(v), v8 = hn::ShiftLeft<3>(v);
  const V d2 = hn::ShiftLeft<1>(d);
  // At green sites, x: 10 v + 8 (W + E) - 2 D - 2 (W2 + E2) + (N2 + S2) + 8, >> 4; 2 - x: turned by 90 degrees.
  const V base_g = hn::Sub(hn::Add(hn::Add(v8, v2), hn::Set(dw, 8)), d2);
  const V at_green_x = hn::ShiftRight<4>(hn::Add(hn::Sub(hn::Add(base_g, hn::ShiftLeft<3>(we)), hn::ShiftLeft<1>(w2)), n2));
  const V at_green_y = hn::ShiftRight<4>(hn::Add(hn::Sub(hn::Add(base_g, hn::ShiftLeft<3>(ns)), hn::ShiftLeft<1>(n2)), w2));
  // At x sites, green: 4 v + 2 (N + S + W + E) - (N2 + S2) - (W2 + E2) + 4, >> 3
  const V nw2 = hn::Add(n2, w2);
  const V at_x_green = hn::ShiftRight<3>(
      hn::Sub(hn::Add(hn::Add(hn::ShiftLeft<2>(v), hn::ShiftLeft<1>(hn::Add(we, ns))), hn::Set(dw, 4)), nw2));
  // At x sites, 2 - x: 12 v + 4 D - 3 (N2 + S2 + W2 + E2) + 8, >> 4
  const V at_x_y = hn::ShiftRight<4>(hn::Sub(hn::Add(hn::Add(hn::Add(v8, hn::ShiftLeft<2>(v)), hn::ShiftLeft<2>(d)), hn::Set(dw, 8)),
                                             hn::Add(nw2, hn::ShiftLeft<1>(nw2))));
  // DemoteTo saturates: the clamp to [0, max] of the scalar definition.
  const auto ch_g = hn::DemoteTo(dt, hn::IfThenElse(green, v, at_x_green));
  const auto ch_x = hn::DemoteTo(dt, hn::IfThenElse(green, at_green_x, v));
  const auto ch_y = hn::DemoteTo(dt, hn::IfThenElse(green, at_green_y, at_x_y));
  T* const out = dst + 3 * c;
  if (x == 0) hn::StoreInterleaved3(ch_x, ch_g, ch_y, dt, out);
  else hn::StoreInterleaved3(ch_y, ch_g, ch_x, dt, out);
}

// The lanes on green sites of a row whose green sites are at even columns (green_even) or odd ones, for vectors
// starting at an even column.
template <class D>
HWY_INLINE hn::Mask<D> green_lanes(D d, bool green_even) {
  const auto even = hn::Eq(hn::And(hn::Iota(d, 0), hn::Set(d, 1)), hn::Zero(d));
  return green_even ? even : hn::Not(even);
}

// Rows [r_begin, r_end): two border columns at each side by the scalar definition, the interior in vectors of
// Lanes(d) pixels from column 2, and what is left of it by one more vector ending at the last interior column,
// overlapping the one before (it writes the same values there): a scalar remainder would cost as much as a
// third of the row's vectors. Interiors narrower than one vector are scalar.
template <class T, bool kMhc, class D, class VectorFn>
void demosaic_rows_with(const DemosaicJob& job, int r_begin, int r_end, D d, VectorFn vector_fn) {
  const int lanes = static_cast<int>(hn::Lanes(d));
  const cv::Mat& raw = *job.raw;
  const int rows = raw.rows, cols = raw.cols, maxv = std::numeric_limits<T>::max();
  const BayerPattern p = job.pattern;
  const auto green_at_even = green_lanes(d, true), green_at_odd = green_lanes(d, false);
  // Vectors start at even columns 2, 2 + lanes, ...; a single-lane target leaves it all to the scalar loop.
  const bool vectors = lanes % 2 == 0 && cols - 4 >= lanes;
  const int vector_end = vectors ? 2 + (cols - 4) / lanes * lanes : 2;
  const int last_start = cols - 2 - lanes;  // of the overlapping vector; odd when cols is: its lane 0 is then odd
  for (int r = r_begin; r < r_end; ++r) {
    const T* row[5];
    for (int k = 0; k < 5; ++k) row[k] = raw.ptr<T>(reflect(r - 2 + k, rows));
    T* const dst = job.out->ptr<T>(r);
    const int here0 = bayer_channel(p, r, 0), here1 = bayer_channel(p, r, 1);
    for (int c = 0; c < 2; ++c) demosaic_edge_pixel<T>(row, c, cols, c ? here1 : here0, c ? here0 : here1, kMhc, maxv, dst);
    const bool green_even = here0 == 1;
    const auto green = green_even ? green_at_even : green_at_odd;
    const int x = green_even ? here1 : here0;
    int c = 2;
    for (; c < vector_end; c += lanes) vector_fn(row, c, green, x, dst);
    if (vectors && c < cols - 2) {
      vector_fn(row, last_start, last_start % 2 == 0 ? green : (green_even ? green_at_odd : green_at_even), x, dst);
    } else {
      for (; c < cols - 2; ++c) demosaic_inner_pixel<T>(row, c, c % 2 ? here1 : here0, c % 2 ? here0 : here1, kMhc, maxv, dst);
    }
    for (c = cols - 2; c < cols; ++c)
      demosaic_edge_pixel<T>(row, c, cols, c % 2 ? here1 : here0, c % 2 ? here0 : here1, kMhc, maxv, dst);
  }
}

template <class T, bool kMhc>
void demosaic_rows(const DemosaicJob& job, int r_begin, int r_end) {
  if constexpr (!kMhc) {
    const hn::ScalableTag<T> d;
    demosaic_rows_with<T, false>(job, r_begin, r_end, d, [d](const T* const row[5], int c, auto green, int x, T* dst) HWY_ATTR {
      bilinear_vector(d, row, c, green, x, dst);
    });
  } else {
    using W = std::conditional_t<sizeof(T) == 1, std::int16_t, std::int32_t>;
    const hn::ScalableTag<W> dw;
    const hn::Rebind<T, decltype(dw)> dt;
    demosaic_rows_with<T, true>(job, r_begin, r_end, dw, [dw, dt](const T* const row[5], int c, auto green, int x, T* dst) HWY_ATTR {
      mhc_vector(dw, dt, row, c, green, x, dst);
    });
  }
}
void demosaic_rows8(const DemosaicJob& job, int r_begin, int r_end) {
  if (job.mhc) demosaic_rows<std::uint8_t, true>(job, r_begin, r_end);
  else demosaic_rows<std::uint8_t, false>(job, r_begin, r_end);
}

void demosaic_rows16(const DemosaicJob& job, int r_begin, int r_end) {
  if (job.mhc) demosaic_rows<std::uint16_t, true>(job, r_begin, r_end);
  else demosaic_rows<std::uint16_t, false>(job, r_begin, r_end);
}

const char* target_name() { return hwy::TargetName(HWY_TARGET); }

}  // namespace bs::vision::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace bs::vision {
namespace detail {
HWY_EXPORT(demosaic_rows8);
HWY_EXPORT(demosaic_rows16);
HWY_EXPORT(target_name);
}  // namespace detail

void demosaic_simd(const cv::Mat& raw, BayerPattern p, bool mhc, cv::Mat& out) {
  const detail::DemosaicJob job{&raw, &out, p, mhc};
  const bool eight = raw.depth() == CV_8U;
  // Stripes of rows on OpenCV's pool, as cvtColor's own demosaic (and the fused path: fused.cpp says why not
  // OpenMP). ~64K pixels per stripe, as cvtColor uses, keeps the pool's overhead small against the work.
  const double stripes = std::max(1.0, static_cast<double>(raw.total()) / (1 << 16));
  cv::parallel_for_(cv::Range(0, raw.rows), [&](const cv::Range& range) {
    if (eight) HWY_DYNAMIC_DISPATCH(detail::demosaic_rows8)(job, range.start, range.end);
    else HWY_DYNAMIC_DISPATCH(detail::demosaic_rows16)(job, range.start, range.end);
  }, stripes);
}

const char* demosaic_simd_target() { return HWY_DYNAMIC_DISPATCH(detail::target_name)(); }

std::vector<std::string> demosaic_simd_targets() {
  std::vector<std::string> names;
  for (const std::int64_t t : hwy::SupportedAndGeneratedTargets()) names.emplace_back(hwy::TargetName(t));
  return names;
}

void demosaic_simd_pin_target(const std::string& name) {
  hwy::SetSupportedTargetsForTest(0);  // the real set again, to look the name up in
  if (name.empty()) return;
  for (const std::int64_t t : hwy::SupportedAndGeneratedTargets())
    if (name == hwy::TargetName(t)) return hwy::SetSupportedTargetsForTest(t);
  throw std::invalid_argument("demosaic_simd_pin_target: '" + name + "' is not an instruction set this build runs here");
}

}  // namespace bs::vision
#endif  // HWY_ONCE
