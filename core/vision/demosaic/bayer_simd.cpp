// SPDX-License-Identifier: GPL-3.0-or-later
// Highway compiles this file once per instruction set (foreach_target.h re-includes it); HWY_DYNAMIC_DISPATCH
// picks the best one the CPU has at run time, so one binary runs AVX-512 where it exists and SSE4 where not, and
// the same source builds NEON on an ARM robot computer.
//
// Why the vector code is bit-exact with the scalar definition (bayer_pixel.h): it evaluates the same integer
// expressions without overflow. Bilinear stays in the sample type: average_round is (a + b + 1) >> 1 exactly, the
// mean of four is rebuilt exactly from two of them (mean4_rounded), and means need no clamp. Malvar-He-Cutler
// works in signed lanes twice as wide as a sample (int16 for 8-bit mosaics: the largest magnitude is
// 28 * 255 + 8 = 7148; int32 for 16-bit), shifts right arithmetically as C++20's >> does on negative ints, and
// clamps to [0, max] with Min/Max as std::clamp does.
//
// Why it is fast: a row alternates two site kinds (green and one of red/blue). Bilinear computes both kinds'
// formulas in every lane and picks per lane with a fixed even/odd mask: twice the (cheap) arithmetic, but no
// shuffles before the one interleaving store (StoreInterleaved3) that writes BGR. Malvar-He-Cutler's formulas
// are dearer, so it splits the row into its two site kinds for free instead (split_load) and computes each
// kind's own two formulas only. The last few interior pixels of a row are one more vector overlapping the one
// before, and the two border columns at each side are the scalar definition itself.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "vision/demosaic/bayer_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>

#include "vision/demosaic/bayer.h"
#include "vision/demosaic/bayer_pixel.h"
#include "vision/demosaic/bayer_simd.h"

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

// (a + b + 1) >> 1 in the sample type. Highway's AverageRound is that on every target but SVE and SVE_256 (SVE
// without SVE2, e.g. Graviton 3, A64FX), where Highway (1.0.3 and, checked in its sources, up to 1.2) computes
// (a + b + 1) >> 1 in the lane type, which wraps when a + b + 1 exceeds the lane's maximum: the aarch64 test under
// qemu found wrong pixels there. (a | b) - ((a ^ b) >> 1) is the same rounded mean and cannot overflow.
template <class V>
HWY_INLINE V average_round(V a, V b) {
#if HWY_TARGET == HWY_SVE || HWY_TARGET == HWY_SVE_256
  return hn::Sub(hn::Or(a, b), hn::ShiftRight<1>(hn::Xor(a, b)));
#else
  return hn::AverageRound(a, b);
#endif
}

// (a + b + c + d + 2) >> 2 in the sample type, without widening: from the rounded pair means ab = (a + b + 1) >> 1
// and cd, it is (ab + cd + 1) >> 1 when both pair sums are even, else (ab + cd) >> 1, i.e. one less when ab + cd
// is odd. (With s1 = a + b, s2 = c + d: 2 ab + 2 cd = s1 + s2 + odd1 + odd2, so (s1 + s2 + 2) / 4 =
// (ab + cd + 1 - (odd1 + odd2) / 2) / 2, floored.)
template <class D, class V>
HWY_INLINE V mean4_rounded(D d, V ab, V cd, V a, V b, V c, V e) {
  const V odd_pair = hn::Or(hn::Xor(a, b), hn::Xor(c, e));
  const V correction = hn::And(hn::And(odd_pair, hn::Xor(ab, cd)), hn::Set(d, 1));
  return hn::Sub(average_round(ab, cd), correction);
}

// Bilinear: Lanes(d) pixels of one row from column c on (`green` marks the lanes on green sites), computed in
// the sample type itself (average_round is (a + b + 1) >> 1 exactly), so a vector holds as many pixels as fit.
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
  const V nw = hn::LoadU(d, up - 1), ne = hn::LoadU(d, up + 1), sw = hn::LoadU(d, down - 1),
          se = hn::LoadU(d, down + 1);
  const V we = average_round(w, e), ns = average_round(n, s);  // at green sites: x and 2 - x
  const V cross = mean4_rounded(d, we, ns, w, e, n, s);        // at x sites: green
  const V top = average_round(nw, ne), bottom = average_round(sw, se);
  const V diagonal = mean4_rounded(d, top, bottom, nw, ne, sw, se);  // at x sites: 2 - x
  const V ch_g = hn::IfThenElse(green, v, cross);
  const V ch_x = hn::IfThenElse(green, we, v);
  const V ch_y = hn::IfThenElse(green, ns, diagonal);
  T* const out = dst + 3 * c;
  if (x == 0)
    hn::StoreInterleaved3(ch_x, ch_g, ch_y, d, out);
  else
    hn::StoreInterleaved3(ch_y, ch_g, ch_x, d, out);
}

static_assert(std::endian::native == std::endian::little, "split_load and merge assume little-endian lanes");

// Malvar-He-Cutler needs signed lanes twice as wide as a sample (its kernels have negative weights). Loading
// 2 N samples as N lanes of twice the width splits them for free: the low half of each lane is the sample at an
// even offset from the load, the high half the one after it (little-endian). So every vector below holds one
// site kind only: the "first" lanes (columns c, c + 2, ...) and the "second" (c + 1, c + 3, ...), each computing
// just the two formulas its sites need, and the results are merged back the same way (low | high << bits).
// Vectors live in locals and arguments only, never in structs or lambda captures: SVE vectors (Highway's SVE and
// SVE2 targets on aarch64) are sizeless types, which C++ allows nowhere else.
template <class DW, class T>
HWY_INLINE hn::Vec<hn::RebindToUnsigned<DW>> load_pairs(DW /*dw*/, const T* p) {
  const hn::RebindToUnsigned<DW> du;
  const hn::Repartition<T, decltype(du)> dt;
  return hn::BitCast(du, hn::LoadU(dt, p));
}

// The sample at the even offset of each pair (p[0], p[2], ...), widened.
template <class DW, class VU>
HWY_INLINE hn::Vec<DW> first_of(DW dw, VU pairs) {
  const hn::RebindToUnsigned<DW> du;
  constexpr int kBits = 4 * sizeof(hn::TFromD<DW>);
  return hn::BitCast(dw, hn::And(pairs, hn::Set(du, static_cast<hn::TFromD<decltype(du)>>((1u << kBits) - 1))));
}

// The sample at the odd offset of each pair (p[1], p[3], ...), widened.
template <class DW, class VU>
HWY_INLINE hn::Vec<DW> second_of(DW dw, VU pairs) {
  constexpr int kBits = 4 * sizeof(hn::TFromD<DW>);
  return hn::BitCast(dw, hn::ShiftRight<kBits>(pairs));
}

// Missing channels at green sites: x (the row's other colour) and y (the column's), times 16 before the shift.
// The taps of one site kind: v its own sample, we / ns the sums of its west + east / north + south neighbours,
// d of its four diagonal ones, n2 / w2 of the samples two rows / two columns away.
template <class DW, class V>
HWY_INLINE void mhc_green(DW dw, V v, V we, V ns, V d, V n2, V w2, V& x, V& y) {
  // 10 v - 2 D + 8 shared; x: + 8 (W + E) - 2 (W2 + E2) + (N2 + S2); y: the same turned by 90 degrees.
  const V base =
      hn::Sub(hn::Add(hn::Add(hn::ShiftLeft<3>(v), hn::ShiftLeft<1>(v)), hn::Set(dw, 8)), hn::ShiftLeft<1>(d));
  x = hn::ShiftRight<4>(hn::Add(hn::Sub(hn::Add(base, hn::ShiftLeft<3>(we)), hn::ShiftLeft<1>(w2)), n2));
  y = hn::ShiftRight<4>(hn::Add(hn::Sub(hn::Add(base, hn::ShiftLeft<3>(ns)), hn::ShiftLeft<1>(n2)), w2));
}

// Missing channels at red/blue sites: green, and y (the colour measured diagonally).
template <class DW, class V>
HWY_INLINE void mhc_colour(DW dw, V v, V we, V ns, V d, V n2, V w2, V& g, V& y) {
  const V v4 = hn::ShiftLeft<2>(v), nw2 = hn::Add(n2, w2);
  // (4 v + 2 (N + S + W + E) - (N2 + S2) - (W2 + E2) + 4) >> 3
  g = hn::ShiftRight<3>(hn::Sub(hn::Add(hn::Add(v4, hn::ShiftLeft<1>(hn::Add(we, ns))), hn::Set(dw, 4)), nw2));
  // (12 v + 4 D - 3 (N2 + S2 + W2 + E2) + 8) >> 4
  y = hn::ShiftRight<4>(
      hn::Sub(hn::Add(hn::Add(hn::Add(hn::ShiftLeft<1>(v4), v4), hn::ShiftLeft<2>(d)), hn::Set(dw, 8)),
              hn::Add(nw2, hn::ShiftLeft<1>(nw2))));
}

// Two results of one channel, first-kind and second-kind lanes, clamped to [0, max] as the scalar definition
// does and merged back into 2 N samples in column order.
template <class DW, class DT>
HWY_INLINE hn::Vec<DT> merge(DW dw, DT dt, hn::Vec<DW> first, hn::Vec<DW> second) {
  const hn::RebindToUnsigned<DW> du;
  constexpr int kBits = 8 * sizeof(hn::TFromD<DT>);
  const auto top = hn::Set(dw, static_cast<hn::TFromD<DW>>((1 << kBits) - 1));
  const auto lo = hn::BitCast(du, hn::Min(hn::Max(first, hn::Zero(dw)), top));
  const auto hi = hn::BitCast(du, hn::Min(hn::Max(second, hn::Zero(dw)), top));
  return hn::BitCast(dt, hn::Or(lo, hn::ShiftLeft<kBits>(hi)));
}

// 2 Lanes(dw) pixels of one row from column c on; `first_green`: whether column c is a green site; `x` the colour
// (0 B or 2 R) of the row's other sites. Writes BGR to dst + 3 c.
template <class DW, class T>
HWY_INLINE void mhc_vector(DW dw, const T* const row[5], int c, bool first_green, int x, T* dst) {
  using V = hn::Vec<DW>;
  const hn::Repartition<T, hn::RebindToUnsigned<DW>> dt;
  // Pairs of samples; suffixes: 0 = the pair at columns (c + 2k, c + 2k + 1), m = the pair before it, p = the one
  // after; up / down are rows r -+ 1, up2 / down2 rows r -+ 2.
  const auto mid_m = load_pairs(dw, row[2] + c - 2), mid0 = load_pairs(dw, row[2] + c),
             mid_p = load_pairs(dw, row[2] + c + 2);
  const auto up0 = load_pairs(dw, row[1] + c), down0 = load_pairs(dw, row[3] + c);
  const V up_m = first_of(dw, load_pairs(dw, row[1] + c - 1)),
          down_m = first_of(dw, load_pairs(dw, row[3] + c - 1));  // column c + 2k - 1
  const V up_p = second_of(dw, load_pairs(dw, row[1] + c + 1)),
          down_p = second_of(dw, load_pairs(dw, row[3] + c + 1));  // column c + 2k + 2
  const auto up2 = load_pairs(dw, row[0] + c), down2 = load_pairs(dw, row[4] + c);
  // Taps of column c + 2k (a): west is the second lane of the pair before, east the second of this pair.
  const V a_v = first_of(dw, mid0);
  const V a_we = hn::Add(second_of(dw, mid_m), second_of(dw, mid0));
  const V a_ns = hn::Add(first_of(dw, up0), first_of(dw, down0));
  const V a_d = hn::Add(hn::Add(up_m, second_of(dw, up0)), hn::Add(down_m, second_of(dw, down0)));
  const V a_n2 = hn::Add(first_of(dw, up2), first_of(dw, down2));
  const V a_w2 = hn::Add(first_of(dw, mid_m), first_of(dw, mid_p));
  // Taps of column c + 2k + 1 (b): west is the first lane of this pair, east the first of the pair after.
  const V b_v = second_of(dw, mid0);
  const V b_we = hn::Add(first_of(dw, mid0), first_of(dw, mid_p));
  const V b_ns = hn::Add(second_of(dw, up0), second_of(dw, down0));
  const V b_d = hn::Add(hn::Add(first_of(dw, up0), up_p), hn::Add(first_of(dw, down0), down_p));
  const V b_n2 = hn::Add(second_of(dw, up2), second_of(dw, down2));
  const V b_w2 = hn::Add(second_of(dw, mid_m), second_of(dw, mid_p));
  // References pick the green and the colour kind without copying (references to sizeless types are fine).
  const V& g_v = first_green ? a_v : b_v;
  const V& c_v = first_green ? b_v : a_v;
  V green_x, green_y, colour_g, colour_y;
  if (first_green) {
    mhc_green(dw, a_v, a_we, a_ns, a_d, a_n2, a_w2, green_x, green_y);
    mhc_colour(dw, b_v, b_we, b_ns, b_d, b_n2, b_w2, colour_g, colour_y);
  } else {
    mhc_green(dw, b_v, b_we, b_ns, b_d, b_n2, b_w2, green_x, green_y);
    mhc_colour(dw, a_v, a_we, a_ns, a_d, a_n2, a_w2, colour_g, colour_y);
  }
  const auto in_order = [dw, dt, first_green](V at_green, V at_colour) HWY_ATTR {
    return first_green ? merge(dw, dt, at_green, at_colour) : merge(dw, dt, at_colour, at_green);
  };
  const auto ch_g = in_order(g_v, colour_g);
  const auto ch_x = in_order(green_x, c_v);
  const auto ch_y = in_order(green_y, colour_y);
  T* const out = dst + 3 * c;
  if (x == 0)
    hn::StoreInterleaved3(ch_x, ch_g, ch_y, dt, out);
  else
    hn::StoreInterleaved3(ch_y, ch_g, ch_x, dt, out);
}

// The lanes on green sites of a vector whose first column is a green site (first_green) or not.
template <class D>
HWY_INLINE hn::Mask<D> green_lanes(D d, bool first_green) {
  const auto even = hn::Eq(hn::And(hn::Iota(d, 0), hn::Set(d, 1)), hn::Zero(d));
  return first_green ? even : hn::Not(even);
}

// Rows [r_begin, r_end): two border columns at each side by the scalar definition, the interior in vectors of
// Lanes(d) pixels from column 2, and what is left of it by one more vector ending at the last interior column,
// overlapping the one before (it writes the same values there): a scalar remainder would cost as much as a
// third of the row's vectors. Interiors narrower than one vector are scalar.
template <class T, bool kMhc, class VectorFn>
void demosaic_rows_with(const DemosaicJob& job, int r_begin, int r_end, int lanes, VectorFn vector_fn) {
  const cv::Mat& raw = *job.raw;
  const int rows = raw.rows, cols = raw.cols, maxv = std::numeric_limits<T>::max();
  const BayerPattern p = job.pattern;
  // Vectors start at even columns 2, 2 + lanes, ...; a single-lane target leaves it all to the scalar loop.
  const bool vectors = lanes % 2 == 0 && cols - 4 >= lanes;
  const int vector_end = vectors ? 2 + (cols - 4) / lanes * lanes : 2;
  const int last_start = cols - 2 - lanes;  // of the overlapping vector; odd when cols is
  for (int r = r_begin; r < r_end; ++r) {
    const T* row[5];
    for (int k = 0; k < 5; ++k) row[k] = raw.ptr<T>(reflect(r - 2 + k, rows));
    T* const dst = job.out->ptr<T>(r);
    const int here0 = bayer_channel(p, r, 0), here1 = bayer_channel(p, r, 1);
    for (int c = 0; c < 2; ++c)
      demosaic_edge_pixel<T>(row, c, cols, c ? here1 : here0, c ? here0 : here1, kMhc, maxv, dst);
    const bool green_even = here0 == 1;
    const int x = green_even ? here1 : here0;
    int c = 2;
    for (; c < vector_end; c += lanes) vector_fn(row, c, green_even, x, dst);
    if (vectors && c < cols - 2) {
      vector_fn(row, last_start, last_start % 2 == 0 ? green_even : !green_even, x, dst);
    } else {
      for (; c < cols - 2; ++c)
        demosaic_inner_pixel<T>(row, c, c % 2 ? here1 : here0, c % 2 ? here0 : here1, kMhc, maxv, dst);
    }
    for (c = cols - 2; c < cols; ++c)
      demosaic_edge_pixel<T>(row, c, cols, c % 2 ? here1 : here0, c % 2 ? here0 : here1, kMhc, maxv, dst);
  }
}

template <class T, bool kMhc>
void demosaic_rows(const DemosaicJob& job, int r_begin, int r_end) {
  if constexpr (!kMhc) {
    const hn::ScalableTag<T> d;
    const auto green_at_even = green_lanes(d, true), green_at_odd = green_lanes(d, false);
    demosaic_rows_with<T, false>(job, r_begin, r_end, static_cast<int>(hn::Lanes(d)),
                                 [&](const T* const row[5], int c, bool first_green, int x, T* dst) HWY_ATTR {
                                   bilinear_vector(d, row, c, first_green ? green_at_even : green_at_odd, x, dst);
                                 });
  } else {
#if HWY_TARGET == HWY_SCALAR
    // One lane: no pairs to split, so the scalar definition does the interior too.
    demosaic_rows_with<T, true>(job, r_begin, r_end, 1, [](const T* const*, int, bool, int, T*) {});
#else
    using W = std::conditional_t<sizeof(T) == 1, std::int16_t, std::int32_t>;
    const hn::ScalableTag<W> dw;
    demosaic_rows_with<T, true>(job, r_begin, r_end, 2 * static_cast<int>(hn::Lanes(dw)),
                                [dw](const T* const row[5], int c, bool first_green, int x, T* dst)
                                    HWY_ATTR { mhc_vector(dw, row, c, first_green, x, dst); });
#endif
  }
}

void demosaic_rows8(const DemosaicJob& job, int r_begin, int r_end) {
  if (job.mhc)
    demosaic_rows<std::uint8_t, true>(job, r_begin, r_end);
  else
    demosaic_rows<std::uint8_t, false>(job, r_begin, r_end);
}

void demosaic_rows16(const DemosaicJob& job, int r_begin, int r_end) {
  if (job.mhc)
    demosaic_rows<std::uint16_t, true>(job, r_begin, r_end);
  else
    demosaic_rows<std::uint16_t, false>(job, r_begin, r_end);
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
  cv::parallel_for_(
      cv::Range(0, raw.rows),
      [&](const cv::Range& range) {
        if (eight)
          HWY_DYNAMIC_DISPATCH(detail::demosaic_rows8)(job, range.start, range.end);
        else
          HWY_DYNAMIC_DISPATCH(detail::demosaic_rows16)(job, range.start, range.end);
      },
      stripes);
}

bool demosaic_simd_uses_highway() { return true; }

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
  throw std::invalid_argument("demosaic_simd_pin_target: '" + name +
                              "' is not an instruction set this build runs here");
}

}  // namespace bs::vision
#endif  // HWY_ONCE
