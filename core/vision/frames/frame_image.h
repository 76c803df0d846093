// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Imported frames (model/frame.h, OpenCV-free) as OpenCV images, and the lens that goes with a frame.
#include <optional>
#include <utility>

#include <opencv2/core.hpp>

#include "model/frame.h"
#include "vision/demosaic/bayer.h"
#include "vision/lens/lens.h"

namespace bs::vision {

// CV_8UC1 / CV_16UC1 (mosaic or grey) or CV_8UC3 / CV_16UC3 (BGR): a deep copy of the frame's pixels.
// Throws std::invalid_argument when the pixel buffer does not match the geometry.
cv::Mat frame_to_mat(const Frame& frame);

// The frame's Bayer pattern, or nullopt for grey / colour frames.
std::optional<BayerPattern> frame_pattern(const Frame& frame);

// The lens and view recorded with the frame (sidecar "lens"); otherwise the paper's lens (195 degree
// equidistant) scaled to the frame's size and the paper's 150 degree view at the frame's size. `from_frame` says
// which.
struct FrameLens {
  Lens lens;
  View view;
  bool from_frame = false;
};
FrameLens lens_for_frame(const Frame& frame);

}  // namespace bs::vision
