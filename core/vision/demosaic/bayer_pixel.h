// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scalar definition of BenchScope's demosaic, one pixel at a time. The reference path (bayer_reference.cpp)
// is built from it alone; the fast path (bayer_simd.cpp) uses it for the two border columns at each side and the
// few interior pixels left after the last full vector, so both agree there by construction.
#include <algorithm>

namespace bs::vision::detail {

// Mirror an index into [0, n) without repeating the edge (OpenCV's BORDER_REFLECT_101); needs n >= 3.
inline int reflect(int i, int n) {
  if (i < 0) return -i;
  if (i >= n) return 2 * n - 2 - i;
  return i;
}

// Our demosaic of the pixel at (r, c) in integers; `at(dr, dc)` reads the mosaic at (r + dr, c + dc). The
// arithmetic is the textbook one scaled to integers, rounded half up and clamped:
//  bilinear  a measured channel is copied; a missing one is the mean of its 2 or 4 nearest samples;
//  MHC       Malvar, He, Cutler (2004), eq. (and Fig. 2): bilinear estimate plus a scaled Laplacian of the
//            measured channel, i.e. their 5x5 kernels, whose weights are multiples of 1/16.
// `here` is the colour measured at (r, c) (0 B, 1 G, 2 R), `row_colour` the one measured at (r, c + 1).
template <class T, class At>
inline void demosaic_pixel(At at, int here, int row_colour, bool mhc, int maxv, T* dst) {
  const int v = at(0, 0);
  const int e = at(0, 1), w = at(0, -1), n = at(-1, 0), s = at(1, 0);
  int ch[3];
  ch[here] = v;
  if (!mhc) {
    if (here == 1) {
      ch[row_colour] = (w + e + 1) >> 1;
      ch[2 - row_colour] = (n + s + 1) >> 1;
    } else {
      ch[1] = (n + s + w + e + 2) >> 2;
      ch[2 - here] = (at(-1, -1) + at(-1, 1) + at(1, -1) + at(1, 1) + 2) >> 2;
    }
  } else {
    const int n2 = at(-2, 0) + at(2, 0), w2 = at(0, -2) + at(0, 2);
    if (here == 1) {
      const int d = at(-1, -1) + at(-1, 1) + at(1, -1) + at(1, 1);
      // Colour in the same row: (10 v + 8 (E + W) - 2 diagonals - 2 (W2 + E2) + (N2 + S2)) / 16; the column
      // colour is the same kernel turned by 90 degrees.
      ch[row_colour] = (10 * v + 8 * (w + e) - 2 * d - 2 * w2 + n2 + 8) >> 4;
      ch[2 - row_colour] = (10 * v + 8 * (n + s) - 2 * d - 2 * n2 + w2 + 8) >> 4;
    } else {
      const int d = at(-1, -1) + at(-1, 1) + at(1, -1) + at(1, 1);
      ch[1] = (4 * v + 2 * (n + s + w + e) - n2 - w2 + 4) >> 3;
      ch[2 - here] = (12 * v + 4 * d - 3 * (n2 + w2) + 8) >> 4;
    }
  }
  for (int k = 0; k < 3; ++k) dst[k] = static_cast<T>(std::clamp(ch[k], 0, maxv));
}

// Pixel (r, c) of a row whose mosaic rows r-2 .. r+2 (top and bottom already reflected) are `row[0..4]`,
// reflecting columns: the slow reader, for the left and right borders.
template <class T>
inline void demosaic_edge_pixel(const T* const row[5], int c, int cols, int here, int row_colour, bool mhc, int maxv,
                                T* dst) {
  const auto at = [&](int dr, int dc) { return static_cast<int>(row[2 + dr][reflect(c + dc, cols)]); };
  demosaic_pixel<T>(at, here, row_colour, mhc, maxv, dst + 3 * c);
}

// Pixel (r, c) at least 2 columns from either side: direct reads.
template <class T>
inline void demosaic_inner_pixel(const T* const row[5], int c, int here, int row_colour, bool mhc, int maxv, T* dst) {
  const auto at = [&](int dr, int dc) { return static_cast<int>(row[2 + dr][c + dc]); };
  demosaic_pixel<T>(at, here, row_colour, mhc, maxv, dst + 3 * c);
}

}  // namespace bs::vision::detail
