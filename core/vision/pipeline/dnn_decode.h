// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Decoding the outputs of detection networks that labs export (ONNX, Caffe, Darknet, TensorFlow through cv::dnn)
// into boxes on the image the detector was given. Three output families are known:
//   SSD     [1, 1, N, 7]    rows [image, class, score, x0, y0, x1, y1], coordinates 0..1 (DetectionOutput);
//   YOLOv5  [1, N, 5 + C]   rows [cx, cy, w, h, objectness, C class scores], coordinates in input pixels;
//   YOLOv8  [1, 4 + C, N]   columns [cx, cy, w, h, C class scores], anchor-free, no objectness, input pixels.
// The YOLO families have N (anchors) far larger than their attribute count, which is how they are told apart.
// SSD networks take the image stretched to their input (boxes scale back per axis); YOLO networks are trained on
// letterboxed inputs (the image scaled by one factor to fit, centred, the rest padded grey), so their boxes are
// mapped back through the letterbox: shifted by the padding, then scaled by the one factor.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/pipeline/detector.h"

namespace bs::vision {

enum class DnnOutputFamily { Ssd, YoloV5, YoloV8 };
const char* to_string(DnnOutputFamily family);

// "1x25200x85" for a blob of that shape.
std::string shape_text(const cv::Mat& blob);

// The family of a network's outputs: the first output whose shape matches one. Throws std::runtime_error naming
// every output's shape when none does.
struct FamilyMatch {
  DnnOutputFamily family;
  std::size_t output_index;
};
FamilyMatch detect_output_family(const std::vector<cv::Mat>& outputs);

// Where an image lies in a letterboxed network input: scaled by min(input W / image W, input H / image H) to
// `content`'s size (rounded), centred (the odd pixel of padding goes right and bottom, as Ultralytics does).
struct Letterbox {
  cv::Size input;    // the network's input
  cv::Size image;    // the image letterboxed into it
  cv::Rect content;  // the image's pixels within the input
};
// Throws std::invalid_argument for an empty size.
Letterbox letterbox_geometry(cv::Size image, cv::Size input);
// The image letterboxed into `input`: resized to the content rectangle (linear interpolation, as
// blobFromImage does), the rest filled with `pad` (114 grey, the value the YOLO families are trained with).
cv::Mat letterbox_image(const cv::Mat& image, cv::Size input, const cv::Scalar& pad = cv::Scalar::all(114));
// A box in network-input pixels mapped back to image pixels through the letterbox, exactly: minus the content's
// origin, times image size / content size per axis (the inverse of the resize, rounding included). Not clipped.
cv::Rect2d letterbox_to_image(const cv::Rect2d& box_in_input, const Letterbox& lb);

struct DecodeOptions {
  cv::Size input_size;  // the network's input (YOLO coordinates are in these pixels)
  cv::Size image_size;  // the image the boxes are for
  // The image was letterboxed into the input (letterbox_image) rather than stretched: boxes map back through
  // letterbox_geometry(image_size, input_size). Default for the YOLO families in dnn_detector.
  bool letterbox = false;
  float min_confidence = 0.5f;
  float nms_threshold = 0.45f;  // IoU above which a lower-scoring box of the same class is dropped (YOLO)
};

// SSD rows: confidence threshold; boxes scaled from 0..1 to the image (or, letterboxed, from 0..1 of the input
// through the letterbox) and clipped (DetectionOutput did the NMS).
std::vector<Detection> decode_ssd(const cv::Mat& out, const DecodeOptions& o);
// YOLOv5: score = objectness x best class score; threshold, then per-class NMS; boxes mapped to the image.
std::vector<Detection> decode_yolov5(const cv::Mat& out, const DecodeOptions& o);
// YOLOv8: score = best class score; threshold, per-class NMS; boxes mapped to the image.
std::vector<Detection> decode_yolov8(const cv::Mat& out, const DecodeOptions& o);
// Detects the family and decodes that output.
std::vector<Detection> decode_detections(const std::vector<cv::Mat>& outputs, const DecodeOptions& o);

}  // namespace bs::vision
