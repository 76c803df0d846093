// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/reproject/triptych.h"

#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "vision/frames/frame_image.h"

namespace bs::vision {

cv::Mat demosaic_frame(const cv::Mat& raw, const Frame& frame, DemosaicMethod method) {
  if (raw.channels() == 3) return raw.clone();
  if (const auto pattern = frame_pattern(frame)) {
    // OpenCV's VNG takes only 8-bit input; our methods and OpenCV's bilinear take both.
    if (method == DemosaicMethod::OpenCvVng && raw.depth() != CV_8U) method = DemosaicMethod::OpenCvBilinear;
    return demosaic(raw, *pattern, method);
  }
  cv::Mat bgr;
  cv::cvtColor(raw, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

TriptychImages render_triptych(const Frame& frame, DemosaicMethod method, const Lens& lens, const View& view,
                               const CancelToken* cancel) {
  return render_triptych(frame_to_mat(frame), frame, method, lens, view, cancel);
}

TriptychImages render_triptych(const cv::Mat& raw, const Frame& frame, DemosaicMethod method, const Lens& lens,
                               const View& view, const CancelToken* cancel) {
  if (lens.width != raw.cols || lens.height != raw.rows)
    throw std::invalid_argument("lens source size " + std::to_string(lens.width) + "x" + std::to_string(lens.height) +
                                " differs from the frame's " + std::to_string(raw.cols) + "x" +
                                std::to_string(raw.rows));
  TriptychImages out;
  if (raw.channels() == 3)
    cv::cvtColor(raw, out.mosaic, cv::COLOR_BGR2GRAY);
  else
    out.mosaic = raw;
  if (cancel) cancel->throw_if_cancelled();
  out.demosaiced = demosaic_frame(raw, frame, method);
  if (cancel) cancel->throw_if_cancelled();
  const ReprojectionLut lut(lens, view);
  if (cancel) cancel->throw_if_cancelled();
  out.reprojected = lut.apply(out.demosaiced);
  return out;
}

cv::Mat window_to_8bit(const cv::Mat& img, double low, double high) {
  if (high <= low) high = low + 1;
  const double scale = 255.0 / (high - low);
  cv::Mat out;
  img.convertTo(out, CV_8U, scale, -low * scale);  // saturate_cast clamps to 0..255
  return out;
}

}  // namespace bs::vision
