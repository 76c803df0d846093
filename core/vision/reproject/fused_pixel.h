// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One output pixel of the fused demosaic + reprojection, written once for the host and for CUDA (nvcc compiles it
// as __host__ __device__): the CUDA kernel (cuda/fused_cuda.cu) runs exactly this code per thread, and the host
// reference (fused_reference) runs it per pixel, so the kernel's arithmetic is tested on every machine, with or
// without a GPU. It computes the same integers as FusedTable (fused.cpp): the lookup position rounded half to even
// onto OpenCV's 1/32-pixel grid, the four bilinear taps demosaiced (bilinear, x4 in integers) from their 3x3
// neighbourhoods, borders reflected without repeating the edge, and the weighted sum rounded once (>> 12).
// No OpenCV, no standard library beyond <cstdint>: nvcc includes this header.
#include <cstdint>

#if defined(__CUDACC__)
#define BS_HOST_DEVICE __host__ __device__
#else
#define BS_HOST_DEVICE
#include <cmath>
#endif

namespace bs::vision::fused_pixel {

// The mosaic and how it is laid out: layout[(row & 1) * 2 + (col & 1)] is the colour (0 B, 1 G, 2 R) at (row, col).
struct Mosaic {
  const std::uint8_t* data;
  int width, height, stride;  // stride in bytes
  int layout[4];
};

BS_HOST_DEVICE inline int reflect(int i, int n) { return i < 0 ? -i : (i >= n ? 2 * n - 2 - i : i); }

BS_HOST_DEVICE inline int at(const Mosaic& m, int r, int c) {
  return m.data[reflect(r, m.height) * m.stride + reflect(c, m.width)];
}

// Bilinear demosaic at (r, c), every channel times 4 (4 x one value, 2 x a sum of two, a sum of four), as
// fused.cpp's rgb4: integers until the single rounding at the end.
BS_HOST_DEVICE inline void rgb4(const Mosaic& m, int r, int c, int out[3]) {
  const int here = m.layout[(r & 1) * 2 + (c & 1)], row_colour = m.layout[(r & 1) * 2 + ((c + 1) & 1)];
  const int w = at(m, r, c - 1), e = at(m, r, c + 1), n = at(m, r - 1, c), s = at(m, r + 1, c);
  if (here == 1) {
    out[1] = 4 * at(m, r, c);
    out[row_colour] = 2 * (w + e);
    out[2 - row_colour] = 2 * (n + s);
  } else {
    out[here] = 4 * at(m, r, c);
    out[1] = w + e + n + s;
    out[2 - here] = at(m, r - 1, c - 1) + at(m, r - 1, c + 1) + at(m, r + 1, c - 1) + at(m, r + 1, c + 1);
  }
}

// Round half to even, as OpenCV's cvRound and std::lrint in the default rounding mode.
BS_HOST_DEVICE inline int round_even(float v) {
#if defined(__CUDA_ARCH__)
  return __float2int_rn(v);
#else
  return static_cast<int>(std::lrint(v));
#endif
}

// The BGR pixel sampled at mosaic position (sx, sy); `fill` when the table has no source there (negative).
BS_HOST_DEVICE inline void sample(const Mosaic& m, float sx, float sy, const std::uint8_t fill[3],
                                  std::uint8_t out[3]) {
  if (sx < 0 || sy < 0) {
    out[0] = fill[0], out[1] = fill[1], out[2] = fill[2];
    return;
  }
  const int qx = round_even(sx * 32.0f), qy = round_even(sy * 32.0f);
  const int x0 = qx >> 5, y0 = qy >> 5, wx1 = qx & 31, wy1 = qy & 31, wx0 = 32 - wx1, wy0 = 32 - wy1;
  int c0[3], c1[3], c2[3], c3[3];
  rgb4(m, y0, x0, c0);
  rgb4(m, y0, x0 + 1, c1);
  rgb4(m, y0 + 1, x0, c2);
  rgb4(m, y0 + 1, x0 + 1, c3);
  for (int k = 0; k < 3; ++k) {
    // Weights sum to 32 * 32 = 1024 and the channels are x4: divide by 4096, rounding.
    const int top = wx0 * c0[k] + wx1 * c1[k], bottom = wx0 * c2[k] + wx1 * c3[k];
    out[k] = static_cast<std::uint8_t>((wy0 * top + wy1 * bottom + 2048) >> 12);
  }
}

}  // namespace bs::vision::fused_pixel
