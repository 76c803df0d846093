// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Demosaic + reprojection in one pass: each output pixel demosaics (bilinear) only the four Bayer taps its bilinear
// sample needs, straight from the mosaic, so no full-size RGB frame is ever written. 8-bit mosaics.
#include <cstdint>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/demosaic/bayer.h"
#include "vision/reproject/fused_kernels.h"

namespace bs::vision {

// The per-output-pixel table of the fused path, built once per lens/view from build_reprojection_map(): where the
// bilinear taps are in the mosaic and their fractions in 1/32 pixel (OpenCV's remap grid), or "no source".
//
// Two kernels compute the same integers (bit-identical output):
//  - vectorised (AVX-512 F+BW+VBMI, chosen at run time): a packed 4-byte entry per pixel (where its 4x4 window
//    is + both fractions) and one record per 16 pixels (tile or gather, see fused_kernels.h), 16 pixels per step;
//    pixels without a source or whose window leaves the mosaic are listed per row and written by the scalar
//    code. Needs an even source width and width * height < 2^22.
//  - scalar: an 8-byte entry per pixel, used otherwise or when asked for.
class FusedTable {
 public:
  enum class Kernel { Auto, Scalar };
  FusedTable(const cv::Mat& map, cv::Size source_size, BayerPattern pattern, Kernel kernel = Kernel::Auto);
  cv::Size output_size() const { return out_; }
  cv::Size source_size() const { return src_; }
  bool vectorised() const { return !packed_.empty(); }
  std::string_view kernel_name() const { return vectorised() ? "AVX-512" : "scalar"; }
  // Vectorised kernel: how many 16-pixel blocks read a tile and how many gather (diagnostics, tests).
  std::size_t tiled_blocks() const;
  std::size_t gather_blocks() const { return blocks_.size() - tiled_blocks(); }

  // CV_8UC1 mosaic (of source_size) -> CV_8UC3 BGR view; `fill` where no source. OpenMP over rows.
  void run(const cv::Mat& mosaic, cv::Mat& out, const cv::Vec3b& fill = {0, 0, 0}) const;

 private:
  struct Entry {
    // >= 0: y0 * width + x0 of the top-left tap (fast path); kNone: no source; <= kBorder: the taps touch the
    // mosaic's edge, and kBorder - (y0 * width + x0) encodes where (slow path with reflection).
    std::int32_t offset;
    std::uint8_t fx, fy;  // fractions in 1/32
    std::uint8_t parity;  // (y0 & 1) * 2 + (x0 & 1)
  };
  struct Special {
    int x;  // output column
    Entry entry;
  };
  static constexpr std::int32_t kNone = -1;  // outside the image circle or the source
  static constexpr std::int32_t kBorder = -2;
  Entry make_entry(float sx, float sy) const;
  template <int L00, int L01, int L10, int L11>
  void run_rows(const cv::Mat& m, cv::Mat& out, const cv::Vec3b& fill) const;

  cv::Size out_, src_;
  BayerPattern pattern_;
  std::vector<Entry> entries_;              // scalar kernel: every output pixel
  std::vector<std::uint32_t> packed_;       // vectorised kernel: every output pixel
  std::vector<detail::FusedBlock> blocks_;  // vectorised kernel: every 16 pixels of a row
  std::vector<Special> specials_;           // vectorised kernel: pixels the scalar code writes, by row
  std::vector<std::size_t> row_specials_;   // specials_ of row y: [row_specials_[y], row_specials_[y + 1])
};

}  // namespace bs::vision
