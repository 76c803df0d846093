// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/fused.h"

#include <cmath>
#include <stdexcept>

namespace bs::vision {
namespace {

constexpr int kFracBits = 5;  // 1/32 pixel, as OpenCV's remap
constexpr int kFrac = 1 << kFracBits;

// Bilinear demosaic at the pixel `p` points to, all three channels times 4 (4 x a single value, 2 x a sum of two,
// a sum of four) so the hot path stays in integers. `s` is the row stride; needs a 1-pixel margin around p.
inline void rgb4(const std::uint8_t* p, int s, int here, int row_colour, int out[3]) {
  if (here == 1) {
    out[1] = 4 * p[0];
    out[row_colour] = 2 * (p[-1] + p[1]);
    out[2 - row_colour] = 2 * (p[-s] + p[s]);
  } else {
    out[here] = 4 * p[0];
    out[1] = p[-1] + p[1] + p[-s] + p[s];
    out[2 - here] = p[-s - 1] + p[-s + 1] + p[s - 1] + p[s + 1];
  }
}

int reflect(int i, int n) { return i < 0 ? -i : i >= n ? 2 * n - 2 - i : i; }

// One output pixel from the 2x2 taps at p. The channel layout of the quad is a template argument, so every
// `here`/`row colour` branch of rgb4 folds away; there are only four layouts (one per quad parity).
template <int H0, int R0, int H1, int R1, int H2, int R2, int H3, int R3>
inline cv::Vec3b quad_pixel(const std::uint8_t* p, int s, int fx, int fy) {
  const int wx1 = fx, wy1 = fy, wx0 = kFrac - wx1, wy0 = kFrac - wy1;
  int c0[3], c1[3], c2[3], c3[3];
  rgb4(p, s, H0, R0, c0);
  rgb4(p + 1, s, H1, R1, c1);
  rgb4(p + s, s, H2, R2, c2);
  rgb4(p + s + 1, s, H3, R3, c3);
  cv::Vec3b out;
  for (int k = 0; k < 3; ++k) {
    // Weights sum to 32 * 32 = 1024 and channel values are x4: divide by 4096, rounding.
    const int top = wx0 * c0[k] + wx1 * c1[k], bottom = wx0 * c2[k] + wx1 * c3[k];
    out[k] = static_cast<std::uint8_t>((wy0 * top + wy1 * bottom + 2048) >> 12);
  }
  return out;
}

// The kernel for a quad whose top-left tap is at (r, c) of `pattern`.
#define BS_QUAD(P)                                                                                          \
  quad_pixel<kCh(P, 0, 0), kCh(P, 0, 1), kCh(P, 0, 1), kCh(P, 0, 2), kCh(P, 1, 0), kCh(P, 1, 1), kCh(P, 1, 1), \
             kCh(P, 1, 2)>

}  // namespace

// Compile-time copy of bayer_channel() for the four quad layouts (offsets r, c of the quad's top-left tap are
// folded into the pattern index by the caller).
namespace {
constexpr int kLayout[4][4] = {{0, 1, 1, 2}, {2, 1, 1, 0}, {1, 2, 0, 1}, {1, 0, 2, 1}};
constexpr int kCh(int pattern, int r, int c) { return kLayout[pattern][(r & 1) * 2 + (c & 1)]; }

// A quad of layout L (the pattern seen from its top-left tap): its four taps are layout L's cells. Selected by a
// switch, not a function pointer, so each kernel inlines into the pixel loop.
template <int L>
inline cv::Vec3b quad(const std::uint8_t* p, int s, int fx, int fy) {
  return BS_QUAD(L)(p, s, fx, fy);
}
#undef BS_QUAD

// Layout of the quad at each parity, for every pattern: constant per frame, so a template argument.
template <int L00, int L01, int L10, int L11>
inline cv::Vec3b pixel_for_parity(int parity, const std::uint8_t* p, int s, int fx, int fy) {
  switch (parity) {
    case 0: return quad<L00>(p, s, fx, fy);
    case 1: return quad<L01>(p, s, fx, fy);
    case 2: return quad<L10>(p, s, fx, fy);
    default: return quad<L11>(p, s, fx, fy);
  }
}

}  // namespace

FusedTable::FusedTable(const cv::Mat& map, cv::Size source_size, BayerPattern pattern)
    : out_(map.size()), src_(source_size), pattern_(pattern) {
  if (map.type() != CV_32FC2) throw std::invalid_argument("the fused path needs a CV_32FC2 map");
  if (source_size.width < 4 || source_size.height < 4) throw std::invalid_argument("source image too small");
  entries_.resize(static_cast<std::size_t>(out_.area()));
  for (int y = 0; y < out_.height; ++y) {
    const auto* row = map.ptr<cv::Vec2f>(y);
    for (int x = 0; x < out_.width; ++x) {
      Entry& e = entries_[static_cast<std::size_t>(y) * out_.width + x];
      const float sx = row[x][0], sy = row[x][1];
      if (sx < 0 || sy < 0) {
        e = {kNone, 0, 0, 0};
        continue;
      }
      // Round half to even, as OpenCV's cvRound: the 1/32 grid then matches remap's exactly.
      const int qx = static_cast<int>(std::lrint(sx * kFrac)), qy = static_cast<int>(std::lrint(sy * kFrac));
      const int x0 = qx >> kFracBits, y0 = qy >> kFracBits;
      const bool inner = x0 >= 1 && y0 >= 1 && x0 + 2 < src_.width && y0 + 2 < src_.height;
      e.offset = inner ? y0 * src_.width + x0 : kBorder - (y0 * src_.width + x0);
      e.fx = static_cast<std::uint8_t>(qx & (kFrac - 1));
      e.fy = static_cast<std::uint8_t>(qy & (kFrac - 1));
      e.parity = static_cast<std::uint8_t>((y0 & 1) * 2 + (x0 & 1));
    }
  }
}

void FusedTable::run(const cv::Mat& mosaic, cv::Mat& out, const cv::Vec3b& fill) const {
  if (mosaic.type() != CV_8UC1 || mosaic.size() != src_)
    throw std::invalid_argument("the fused path needs an 8-bit mosaic of the size the table was built for");
  // Offsets in the table are y0 * width + x0: a continuous mosaic (the usual case) is used in place.
  const cv::Mat m = mosaic.isContinuous() ? mosaic : mosaic.clone();
  out.create(out_, CV_8UC3);
  // Shifting a pattern by one row or column gives another pattern: BGGR -> GBRG (column), GRBG (row), RGGB (both).
  switch (pattern_) {
    case BayerPattern::BGGR: run_rows<0, 3, 2, 1>(m, out, fill); break;
    case BayerPattern::RGGB: run_rows<1, 2, 3, 0>(m, out, fill); break;
    case BayerPattern::GRBG: run_rows<2, 1, 0, 3>(m, out, fill); break;
    case BayerPattern::GBRG: run_rows<3, 0, 1, 2>(m, out, fill); break;
  }
}

template <int L00, int L01, int L10, int L11>
void FusedTable::run_rows(const cv::Mat& m, cv::Mat& out, const cv::Vec3b& fill) const {
  const int stride = src_.width;
  const int width = src_.width, height = src_.height;
#pragma omp parallel for schedule(static)
  for (int y = 0; y < out_.height; ++y) {
    auto* dst = out.ptr<cv::Vec3b>(y);
    const Entry* e = &entries_[static_cast<std::size_t>(y) * out_.width];
    for (int x = 0; x < out_.width; ++x, ++e) {
      if (e->offset == kNone) {
        dst[x] = fill;
        continue;
      }
      const std::uint8_t* p;
      int s;
      std::uint8_t window[16];
      if (e->offset >= 0) {
        p = m.data + e->offset;
        s = stride;
      } else {
        // Taps at the mosaic's edge: a reflected 4x4 copy around them, same arithmetic (rare: only views that
        // reach the sensor's border).
        const int idx = kBorder - e->offset, y0 = idx / width, x0 = idx % width;
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c)
            window[r * 4 + c] = m.at<std::uint8_t>(reflect(y0 - 1 + r, height), reflect(x0 - 1 + c, width));
        p = window + 5;
        s = 4;
      }
      dst[x] = pixel_for_parity<L00, L01, L10, L11>(e->parity, p, s, e->fx, e->fy);
    }
  }
}

}  // namespace bs::vision
