// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's Figure 3: a raw capture as (a) the grey Bayer mosaic, (b) demosaiced, (c) reprojected to a
// rectilinear view. Used by the GUI's frame triptych (widgets/frame_triptych) and the figure export, so both show
// the same pixels.
#include <opencv2/core.hpp>

#include "model/frame.h"
#include "util/cancel.h"
#include "vision/demosaic/bayer.h"
#include "vision/lens/lens.h"

namespace bs::vision {

struct TriptychImages {
  cv::Mat mosaic;       // (a) CV_8UC1 / CV_16UC1: the samples as recorded (a colour frame: its grey version)
  cv::Mat demosaiced;   // (b) CV_8UC3 / CV_16UC3 BGR
  cv::Mat reprojected;  // (c) same type as (b), view.width x view.height
};

// Demosaics a mosaic frame with `method` (a colour frame is used as is, a grey one is shown grey in (b) and (c))
// and reprojects through lens + view. Throws std::invalid_argument for a frame whose size differs from the lens's
// source size. Checks `cancel` between the stages.
TriptychImages render_triptych(const Frame& frame, DemosaicMethod method, const Lens& lens, const View& view,
                               const CancelToken* cancel = nullptr);

// The same from the frame's pixels already in a Mat (frame_to_mat); `frame` gives the pattern and bit depth.
TriptychImages render_triptych(const cv::Mat& raw, const Frame& frame, DemosaicMethod method, const Lens& lens,
                               const View& view, const CancelToken* cancel = nullptr);

// Only the demosaic stage (b), as render_triptych does it.
cv::Mat demosaic_frame(const cv::Mat& raw, const Frame& frame, DemosaicMethod method);

// Window/level for display: maps [low, high] linearly to 0..255 (clamped), 8-bit result with the same channels.
cv::Mat window_to_8bit(const cv::Mat& img, double low, double high);

// The full-scale window of a frame: [0, 2^bit_depth - 1].
inline double full_scale(const Frame& frame) { return static_cast<double>((1 << frame.bit_depth) - 1); }

}  // namespace bs::vision
