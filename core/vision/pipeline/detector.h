// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pipeline's detection stage: OpenCV's HOG people detector built in, or a detection network through cv::dnn
// from model files the user points to (ONNX, Caffe, TensorFlow, Darknet) whose outputs are SSD, YOLOv5 or YOLOv8.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

namespace bs::vision {

struct Detection {
  cv::Rect box;       // in the image given to the detector
  double score = 0;   // HOG: SVM margin; SSD: confidence 0..1
  int class_id = -1;  // SSD class; -1 for HOG
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

// A detection network read by cv::dnn (ONNX, Caffe .caffemodel + .prototxt, TensorFlow .pb + .pbtxt, Darknet
// .weights + .cfg). Its output family (SSD, YOLOv5, YOLOv8: vision/dnn_decode.h) is found by one forward pass of
// a blank image when the detector is made; the preprocessing defaults follow the family unless given.
struct DnnOptions {
  std::string model, config;  // config empty for ONNX / frozen TensorFlow graphs that need none
  // Empty: 300x300 is tried first (SSD), then 640x640 (YOLO; also taken when a YOLO family answers at 300x300).
  cv::Size input_size{};
  // Empty: SSD (pixel - 127.5) / 127.5, YOLO pixel / 255.
  std::optional<double> scale;
  std::optional<cv::Scalar> mean;
  bool swap_rb = true;
  // Empty: YOLO families letterbox (aspect ratio kept, padded with 114 grey, boxes mapped back through it:
  // vision/dnn_decode.h), SSD stretches the image to the input.
  std::optional<bool> letterbox;
  float min_confidence = 0.5f;
  float nms_threshold = 0.45f;
};
struct DnnDetectorInfo {
  std::string family;   // "SSD", "YOLOv5", "YOLOv8"
  cv::Size input_size;  // as used
  double scale = 0;
  cv::Scalar mean;
  bool letterbox = false;
};
// What a detection network is: its output family, the input size it runs at and the preprocessing that family
// takes (given values win). Found by forward passes of a blank image as described at DnnOptions. Throws
// std::runtime_error starting with `name` when the network runs at no size tried or its outputs are of no known
// family (the message then lists the output shapes).
DnnDetectorInfo probe_detector_network(cv::dnn::Net& net, const DnnOptions& options, const std::string& name);
// Reads a model file (and its config) with cv::dnn::readNet; throws std::runtime_error naming the file.
cv::dnn::Net read_detector_network(const std::string& model, const std::string& config);
// Throws std::runtime_error naming the file when OpenCV cannot read the model or its outputs are of no known
// family (the message then lists the output shapes).
Detector dnn_detector(const DnnOptions& options, DnnDetectorInfo* info = nullptr);
// The same for a network already in memory (tests, built-in architectures); `name` is used in errors.
Detector dnn_detector(cv::dnn::Net net, const DnnOptions& options, const std::string& name,
                      DnnDetectorInfo* info = nullptr);
// Parses an SSD detection output blob (1 x 1 x N x 7) into boxes for an image of `size`; rows below the
// confidence threshold or with an image id < 0 are skipped. Exposed for tests.
std::vector<Detection> parse_ssd_output(const cv::Mat& out, cv::Size size, float min_confidence);

// Draws the boxes (and their scores) onto a copy of the image.
cv::Mat draw_detections(const cv::Mat& bgr, const std::vector<Detection>& detections);

}  // namespace bs::vision
