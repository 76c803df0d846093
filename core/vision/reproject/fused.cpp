// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/reproject/fused.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/core/utility.hpp>

#include "vision/reproject/fused_kernels.h"

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

// Compile-time copy of bayer_channel(): colour (0 B, 1 G, 2 R) at (r, c) of a pattern index.
constexpr int kLayout[4][4] = {{0, 1, 1, 2}, {2, 1, 1, 0}, {1, 2, 0, 1}, {1, 0, 2, 1}};
constexpr int kCh(int pattern, int r, int c) { return kLayout[pattern][(r & 1) * 2 + (c & 1)]; }

// One output pixel from the 2x2 taps at p, for a quad whose top-left tap has layout L (the pattern seen from
// that tap). The layout is a template argument, so every `here`/`row colour` branch of rgb4 folds away.
template <int L>
inline cv::Vec3b quad(const std::uint8_t* p, int s, int fx, int fy) {
  const int wx1 = fx, wy1 = fy, wx0 = kFrac - wx1, wy0 = kFrac - wy1;
  int c0[3], c1[3], c2[3], c3[3];
  rgb4(p, s, kCh(L, 0, 0), kCh(L, 0, 1), c0);
  rgb4(p + 1, s, kCh(L, 0, 1), kCh(L, 0, 2), c1);
  rgb4(p + s, s, kCh(L, 1, 0), kCh(L, 1, 1), c2);
  rgb4(p + s + 1, s, kCh(L, 1, 1), kCh(L, 1, 2), c3);
  cv::Vec3b out;
  for (int k = 0; k < 3; ++k) {
    // Weights sum to 32 * 32 = 1024 and channel values are x4: divide by 4096, rounding.
    const int top = wx0 * c0[k] + wx1 * c1[k], bottom = wx0 * c2[k] + wx1 * c3[k];
    out[k] = static_cast<std::uint8_t>((wy0 * top + wy1 * bottom + 2048) >> 12);
  }
  return out;
}

// Layouts of the quad at each tap parity, for the frame's pattern (template arguments: constant per frame).
template <int L00, int L01, int L10, int L11>
inline cv::Vec3b pixel_for_parity(int parity, const std::uint8_t* p, int s, int fx, int fy) {
  switch (parity) {
    case 0:
      return quad<L00>(p, s, fx, fy);
    case 1:
      return quad<L01>(p, s, fx, fy);
    case 2:
      return quad<L10>(p, s, fx, fy);
    default:
      return quad<L11>(p, s, fx, fy);
  }
}

}  // namespace

FusedTable::Entry FusedTable::make_entry(float sx, float sy) const {
  if (sx < 0 || sy < 0) return {kNone, 0, 0, 0};
  // Round half to even, as OpenCV's cvRound: the 1/32 grid then matches remap's exactly.
  const int qx = static_cast<int>(std::lrint(sx * kFrac)), qy = static_cast<int>(std::lrint(sy * kFrac));
  const int x0 = qx >> kFracBits, y0 = qy >> kFracBits;
  const bool inner = x0 >= 1 && y0 >= 1 && x0 + 2 < src_.width && y0 + 2 < src_.height;
  Entry e;
  e.offset = inner ? y0 * src_.width + x0 : kBorder - (y0 * src_.width + x0);
  e.fx = static_cast<std::uint8_t>(qx & (kFrac - 1));
  e.fy = static_cast<std::uint8_t>(qy & (kFrac - 1));
  e.parity = static_cast<std::uint8_t>((y0 & 1) * 2 + (x0 & 1));
  return e;
}

FusedTable::FusedTable(const cv::Mat& map, cv::Size source_size, BayerPattern pattern, Kernel kernel)
    : out_(map.size()), src_(source_size), pattern_(pattern) {
  if (map.type() != CV_32FC2) throw std::invalid_argument("the fused path needs a CV_32FC2 map");
  if (source_size.width < 4 || source_size.height < 4) throw std::invalid_argument("source image too small");
  const bool vector = kernel == Kernel::Auto && detail::fused_avx512_supported() && src_.width % 2 == 0 &&
                      static_cast<std::int64_t>(src_.width) * src_.height <= detail::kPackedMaxPixels;
  const auto n = static_cast<std::size_t>(out_.area());
  if (!vector) {
    entries_.resize(n);
    for (int y = 0; y < out_.height; ++y) {
      const auto* row = map.ptr<cv::Vec2f>(y);
      for (int x = 0; x < out_.width; ++x)
        entries_[static_cast<std::size_t>(y) * out_.width + x] = make_entry(row[x][0], row[x][1]);
    }
    return;
  }
  packed_.resize(n);
  const int blocks_per_row = (out_.width + detail::kBlockPixels - 1) / detail::kBlockPixels;
  blocks_.resize(static_cast<std::size_t>(blocks_per_row) * out_.height);
  row_specials_.reserve(static_cast<std::size_t>(out_.height) + 1);
  for (int y = 0; y < out_.height; ++y) {
    const auto* row = map.ptr<cv::Vec2f>(y);
    row_specials_.push_back(specials_.size());
    for (int b = 0; b < blocks_per_row; ++b) {
      const int x_begin = b * detail::kBlockPixels, x_end = std::min(out_.width, x_begin + detail::kBlockPixels);
      Entry block[detail::kBlockPixels];
      // Window top-left (column, row) of every inner pixel, and the box they span.
      int left = src_.width, right = -1, top = src_.height, bottom = -1;
      for (int x = x_begin; x < x_end; ++x) {
        const Entry e = block[x - x_begin] = make_entry(row[x][0], row[x][1]);
        if (e.offset < 0) continue;
        const int wx = e.offset % src_.width - 1, wy = e.offset / src_.width - 1;
        left = std::min(left, wx), right = std::max(right, wx), top = std::min(top, wy), bottom = std::max(bottom, wy);
      }
      detail::FusedBlock& info = blocks_[static_cast<std::size_t>(y) * blocks_per_row + b];
      const bool tiled = right >= 0 && right - left + 4 <= 64 && bottom - top < detail::kMaxTileRows;
      if (tiled) {
        info.base = top * src_.width + left;
        info.rows = static_cast<std::uint8_t>(bottom - top + 1);
        info.bytes = static_cast<std::uint8_t>(right - left + 4);
      }
      for (int x = x_begin; x < x_end; ++x) {
        const Entry& e = block[x - x_begin];
        std::uint32_t& packed = packed_[static_cast<std::size_t>(y) * out_.width + x];
        if (e.offset < 0) {
          packed = detail::kPackedSpecial;
          specials_.push_back({x, e});
          continue;
        }
        const auto fractions = static_cast<std::uint32_t>(e.fx) << 22 | static_cast<std::uint32_t>(e.fy) << 27;
        const int wx = e.offset % src_.width - 1, wy = e.offset / src_.width - 1;
        if (tiled)
          packed =
              static_cast<std::uint32_t>((wx - left) | (wy - top) << 6 | (wx & 1) << 9 | (wy & 1) << 10) | fractions;
        else
          packed = static_cast<std::uint32_t>(wy * src_.width + wx) | fractions;
      }
    }
  }
  row_specials_.push_back(specials_.size());
}

std::size_t FusedTable::tiled_blocks() const {
  return static_cast<std::size_t>(
      std::count_if(blocks_.begin(), blocks_.end(), [](const detail::FusedBlock& b) { return b.rows > 0; }));
}

void FusedTable::run(const cv::Mat& mosaic, cv::Mat& out, const cv::Vec3b& fill) const {
  if (mosaic.type() != CV_8UC1 || mosaic.size() != src_)
    throw std::invalid_argument("the fused path needs an 8-bit mosaic of the size the table was built for");
  // Offsets in the table are y0 * width + x0: a continuous mosaic (the usual case) is used in place.
  const cv::Mat m = mosaic.isContinuous() ? mosaic : mosaic.clone();
  out.create(out_, CV_8UC3);
  // Shifting a pattern by one row or column gives another pattern: BGGR -> GBRG (column), GRBG (row), RGGB (both).
  switch (pattern_) {
    case BayerPattern::BGGR:
      run_rows<0, 3, 2, 1>(m, out, fill);
      break;
    case BayerPattern::RGGB:
      run_rows<1, 2, 3, 0>(m, out, fill);
      break;
    case BayerPattern::GRBG:
      run_rows<2, 1, 0, 3>(m, out, fill);
      break;
    case BayerPattern::GBRG:
      run_rows<3, 0, 1, 2>(m, out, fill);
      break;
  }
}

template <int L00, int L01, int L10, int L11>
void FusedTable::run_rows(const cv::Mat& m, cv::Mat& out, const cv::Vec3b& fill) const {
  const int width = src_.width, height = src_.height;
  // One output pixel the scalar way, from any entry (border taps through a reflected 4x4 copy).
  const auto scalar_pixel = [&](const Entry& e) {
    if (e.offset == kNone) return fill;
    if (e.offset >= 0) return pixel_for_parity<L00, L01, L10, L11>(e.parity, m.data + e.offset, width, e.fx, e.fy);
    const int idx = kBorder - e.offset, y0 = idx / width, x0 = idx % width;
    std::uint8_t window[16];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        window[r * 4 + c] = m.at<std::uint8_t>(reflect(y0 - 1 + r, height), reflect(x0 - 1 + c, width));
    return pixel_for_parity<L00, L01, L10, L11>(e.parity, window + 5, 4, e.fx, e.fy);
  };
  // Blue's column and row parity, for the vector kernel: the layout index of the pattern's (0, 0) cell is L00.
  const int blue_col = kCh(L00, 0, 0) == 0 || kCh(L00, 1, 0) == 0 ? 0 : 1;
  const int blue_row = kCh(L00, 0, 0) == 0 || kCh(L00, 0, 1) == 0 ? 0 : 1;
  const std::size_t blocks_per_row =
      (static_cast<std::size_t>(out_.width) + detail::kBlockPixels - 1) / detail::kBlockPixels;
  const auto rows = [&](int y_begin, int y_end) {
    for (int y = y_begin; y < y_end; ++y) {
      auto* dst = out.ptr<cv::Vec3b>(y);
      const std::size_t first = static_cast<std::size_t>(y) * out_.width;
      if (vectorised()) {
        detail::fused_row_avx512(packed_.data() + first, blocks_.data() + static_cast<std::size_t>(y) * blocks_per_row,
                                 out_.width, m.data, width, blue_col, blue_row, out.ptr<std::uint8_t>(y));
        for (std::size_t i = row_specials_[static_cast<std::size_t>(y)];
             i < row_specials_[static_cast<std::size_t>(y) + 1]; ++i)
          dst[specials_[i].x] = scalar_pixel(specials_[i].entry);
      } else {
        for (int x = 0; x < out_.width; ++x) dst[x] = scalar_pixel(entries_[first + static_cast<std::size_t>(x)]);
      }
    }
  };
  // Rows in stripes on OpenCV's thread pool (TBB here), not OpenMP: the caller waits only for stripes that were
  // taken, so on a shared machine a worker that does not get a core costs nothing (an OpenMP team waits at its
  // barrier for every thread, a 4 ms scheduler tick when one is descheduled), and our work and OpenCV's stages
  // in the same pipeline share one pool instead of two spinning against each other.
  cv::parallel_for_(
      cv::Range(0, out_.height), [&](const cv::Range& r) { rows(r.start, r.end); }, std::max(1.0, out_.height / 16.0));
}

}  // namespace bs::vision
