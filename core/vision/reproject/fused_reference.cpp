// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/reproject/fused_reference.h"

#include <stdexcept>

namespace bs::vision {

fused_pixel::Mosaic fused_pixel_mosaic(const cv::Mat& mosaic, BayerPattern pattern) {
  if (mosaic.type() != CV_8UC1 || mosaic.cols < 2 || mosaic.rows < 2)
    throw std::invalid_argument("the fused path needs an 8-bit mosaic of at least 2x2 pixels");
  fused_pixel::Mosaic m{mosaic.data, mosaic.cols, mosaic.rows, static_cast<int>(mosaic.step[0]), {}};
  for (int k = 0; k < 4; ++k) m.layout[k] = bayer_channel(pattern, k >> 1, k & 1);
  return m;
}

cv::Mat fused_reference(const cv::Mat& map, const cv::Mat& mosaic, BayerPattern pattern, const cv::Vec3b& fill) {
  if (map.type() != CV_32FC2) throw std::invalid_argument("the fused path needs a CV_32FC2 map");
  const fused_pixel::Mosaic m = fused_pixel_mosaic(mosaic, pattern);
  cv::Mat out(map.size(), CV_8UC3);
  const std::uint8_t f[3] = {fill[0], fill[1], fill[2]};
  for (int y = 0; y < map.rows; ++y) {
    const auto* src = map.ptr<cv::Vec2f>(y);
    auto* dst = out.ptr<cv::Vec3b>(y);
    for (int x = 0; x < map.cols; ++x) fused_pixel::sample(m, src[x][0], src[x][1], f, dst[x].val);
  }
  return out;
}

}  // namespace bs::vision
