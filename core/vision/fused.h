// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Demosaic + reprojection in one pass: each output pixel demosaics (bilinear) only the four Bayer taps its bilinear
// sample needs, straight from the mosaic, so no full-size RGB frame is ever written. 8-bit mosaics.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/bayer.h"

namespace bs::vision {

// The per-output-pixel table of the fused path, built once per lens/view from build_reprojection_map():
// the mosaic offset of the top-left tap and 5-bit fractions (as OpenCV's remap uses), or a "no source" mark.
class FusedTable {
 public:
  FusedTable(const cv::Mat& map, cv::Size source_size, BayerPattern pattern);
  cv::Size output_size() const { return out_; }
  cv::Size source_size() const { return src_; }

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
  static constexpr std::int32_t kNone = -1;    // outside the image circle or the source
  static constexpr std::int32_t kBorder = -2;
  template <int L00, int L01, int L10, int L11>
  void run_rows(const cv::Mat& m, cv::Mat& out, const cv::Vec3b& fill) const;
  std::vector<Entry> entries_;
  cv::Size out_, src_;
  BayerPattern pattern_;
};

}  // namespace bs::vision
