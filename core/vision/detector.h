// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pipeline's detection stage: OpenCV's HOG people detector built in, or any SSD-style network through cv::dnn
// from model files the user points to (Caffe, TensorFlow, ONNX; output rows [image, class, score, x0, y0, x1, y1]).
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace bs::vision {

struct Detection {
  cv::Rect box;        // in the image given to the detector
  double score = 0;    // HOG: SVM margin; SSD: confidence 0..1
  int class_id = -1;   // SSD class; -1 for HOG
};

using Detector = std::function<std::vector<Detection>(const cv::Mat& bgr)>;

// Runs `inner` on the image downscaled by `scale` (area interpolation; 1 = unchanged) and maps its boxes back to
// the full-size image (divided by the scale, clipped to the image). How HOG is deployed in practice: its cost
// grows with the pixel count, and people far enough to be small are lost anyway at the detection window's size.
// Throws std::invalid_argument unless 0 < scale <= 1.
Detector scaled_detector(Detector inner, double scale);

// HOG + linear SVM (Dalal-Triggs) with OpenCV's default people model, run through scaled_detector(scale)
// (0.5 halves a 1280x1024 frame, which keeps detection time reasonable on small CPUs); boxes are in full-size pixels.
Detector hog_people_detector(double scale = 0.5);

struct DnnOptions {
  std::string model, config;  // config empty for ONNX / frozen TensorFlow graphs that need none
  cv::Size input_size{300, 300};
  double scale = 1.0 / 127.5;  // SSD MobileNet: (pixel - 127.5) / 127.5
  cv::Scalar mean{127.5, 127.5, 127.5};
  bool swap_rb = true;
  float min_confidence = 0.5f;
};
// Throws std::runtime_error naming the file when OpenCV cannot read the model.
Detector dnn_ssd_detector(const DnnOptions& options);
// Parses an SSD detection output blob (1 x 1 x N x 7) into boxes for an image of `size`; rows below the
// confidence threshold or with an image id < 0 are skipped. Exposed for tests.
std::vector<Detection> parse_ssd_output(const cv::Mat& out, cv::Size size, float min_confidence);

// Draws the boxes (and their scores) onto a copy of the image.
cv::Mat draw_detections(const cv::Mat& bgr, const std::vector<Detection>& detections);

}  // namespace bs::vision
