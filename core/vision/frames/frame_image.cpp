// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/frames/frame_image.h"

#include <cstring>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace bs::vision {

cv::Mat frame_to_mat(const Frame& frame) {
  if (frame.width < 1 || frame.height < 1 || (frame.channels != 1 && frame.channels != 3))
    throw std::invalid_argument("frame " + frame.label + ": invalid geometry");
  if (frame.pixels.size() != frame.expected_bytes())
    throw std::invalid_argument("frame " + frame.label + ": " + std::to_string(frame.pixels.size()) +
                                " bytes of pixels, the geometry needs " + std::to_string(frame.expected_bytes()));
  const int depth = frame.bit_depth > 8 ? CV_16U : CV_8U;
  cv::Mat m(frame.height, frame.width, CV_MAKETYPE(depth, frame.channels));
  std::memcpy(m.data, frame.pixels.data(), frame.pixels.size());  // a fresh Mat is continuous
  return m;
}

std::optional<BayerPattern> frame_pattern(const Frame& frame) {
  if (!frame.is_mosaic()) return std::nullopt;
  return bayer_pattern_from_string(frame.pattern);
}

FrameLens lens_for_frame(const Frame& frame) {
  FrameLens out;
  if (!frame.lens_json.empty()) {
    try {
      auto [lens, view] = lens_from_json(nlohmann::json::parse(frame.lens_json));
      if (lens.width == frame.width && lens.height == frame.height) {
        out.lens = lens;
        out.view = view;
        out.from_frame = true;
        return out;
      }
    } catch (const std::exception&) {
      // A damaged or foreign lens record: fall back to the paper's lens below.
    }
  }
  out.lens = Lens::paper();
  out.lens.r_pp *= static_cast<double>(out.lens.width) / frame.width;  // keep 195 degrees across the width
  out.lens.width = frame.width;
  out.lens.height = frame.height;
  out.view.width = frame.width;
  out.view.height = frame.height;
  return out;
}

}  // namespace bs::vision
