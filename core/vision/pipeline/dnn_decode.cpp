// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/dnn_decode.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

namespace bs::vision {

const char* to_string(DnnOutputFamily family) {
  switch (family) {
    case DnnOutputFamily::Ssd:
      return "SSD";
    case DnnOutputFamily::YoloV5:
      return "YOLOv5";
    case DnnOutputFamily::YoloV8:
      return "YOLOv8";
  }
  return "?";
}

Letterbox letterbox_geometry(cv::Size image, cv::Size input) {
  if (image.area() <= 0 || input.area() <= 0) throw std::invalid_argument("letterboxing needs two non-empty sizes");
  const double s =
      std::min(static_cast<double>(input.width) / image.width, static_cast<double>(input.height) / image.height);
  const int w = std::clamp(static_cast<int>(std::lround(image.width * s)), 1, input.width);
  const int h = std::clamp(static_cast<int>(std::lround(image.height * s)), 1, input.height);
  return {input, image, cv::Rect((input.width - w) / 2, (input.height - h) / 2, w, h)};
}

cv::Mat letterbox_image(const cv::Mat& image, cv::Size input, const cv::Scalar& pad) {
  const Letterbox lb = letterbox_geometry(image.size(), input);
  cv::Mat out(input, image.type(), pad);
  if (lb.content.size() == image.size())
    image.copyTo(out(lb.content));
  else
    cv::resize(image, out(lb.content), lb.content.size(), 0, 0, cv::INTER_LINEAR);
  return out;
}

cv::Rect2d letterbox_to_image(const cv::Rect2d& b, const Letterbox& lb) {
  const double sx = static_cast<double>(lb.image.width) / lb.content.width;
  const double sy = static_cast<double>(lb.image.height) / lb.content.height;
  return {(b.x - lb.content.x) * sx, (b.y - lb.content.y) * sy, b.width * sx, b.height * sy};
}

std::string shape_text(const cv::Mat& blob) {
  std::string s;
  for (int i = 0; i < blob.dims; ++i) s += (i ? "x" : "") + std::to_string(blob.size[i]);
  return s.empty() ? "empty" : s;
}

namespace {

// The dimensions without leading 1s beyond the batch: [1, 1, N, 7] stays 4-D, [1, N, K] 3-D.
bool is_ssd(const cv::Mat& m) { return m.dims == 4 && m.size[0] == 1 && m.size[1] == 1 && m.size[3] == 7; }
// YOLO heads: 3-D, batch 1, many anchors against a handful of attributes (at least one class).
bool is_yolov5(const cv::Mat& m) { return m.dims == 3 && m.size[0] == 1 && m.size[2] >= 6 && m.size[1] > m.size[2]; }
bool is_yolov8(const cv::Mat& m) { return m.dims == 3 && m.size[0] == 1 && m.size[1] >= 5 && m.size[2] > m.size[1]; }

void require_float(const cv::Mat& m, const char* family) {
  if (m.depth() != CV_32F)
    throw std::runtime_error(std::string(family) + " output " + shape_text(m) + " is not 32-bit float");
}

struct Candidate {
  cv::Rect2d box;  // in input pixels
  float score;
  int class_id;
};

// How boxes in input pixels go back to the image: through the letterbox, or (stretched) a letterbox whose content
// is the whole input, i.e. scaled per axis.
Letterbox input_to_image(const DecodeOptions& o) {
  return o.letterbox ? letterbox_geometry(o.image_size, o.input_size)
                     : Letterbox{o.input_size, o.image_size, cv::Rect(cv::Point(0, 0), o.input_size)};
}

// A box in image pixels (not yet rounded) to whole pixels, clipped to the image.
cv::Rect to_pixels(const cv::Rect2d& b, cv::Size image) {
  const cv::Rect r(cv::Point(cvRound(b.x), cvRound(b.y)), cv::Point(cvRound(b.x + b.width), cvRound(b.y + b.height)));
  return r & cv::Rect(cv::Point(0, 0), image);
}

// Per-class NMS (a person box does not suppress a bicycle box), then the boxes mapped from the network's input
// to the image and clipped.
std::vector<Detection> nms_and_map(const std::vector<Candidate>& cands, const DecodeOptions& o) {
  std::map<int, std::vector<std::size_t>> by_class;
  for (std::size_t i = 0; i < cands.size(); ++i) by_class[cands[i].class_id].push_back(i);
  const Letterbox lb = input_to_image(o);
  std::vector<Detection> dets;
  for (const auto& [cls, idx] : by_class) {
    std::vector<cv::Rect2d> boxes;
    std::vector<float> scores;
    for (std::size_t i : idx) boxes.push_back(cands[i].box), scores.push_back(cands[i].score);
    std::vector<int> keep;
    cv::dnn::NMSBoxes(boxes, scores, o.min_confidence, o.nms_threshold, keep);
    for (int k : keep) {
      const cv::Rect clipped = to_pixels(letterbox_to_image(boxes[static_cast<std::size_t>(k)], lb), o.image_size);
      if (clipped.area() > 0) dets.push_back({clipped, scores[static_cast<std::size_t>(k)], cls});
    }
  }
  std::sort(dets.begin(), dets.end(), [](const Detection& a, const Detection& b) { return a.score > b.score; });
  return dets;
}

void check_sizes(const DecodeOptions& o) {
  if (o.input_size.area() <= 0 || o.image_size.area() <= 0)
    throw std::invalid_argument("decoding needs the network's input size and the image size");
}

}  // namespace

FamilyMatch detect_output_family(const std::vector<cv::Mat>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (is_ssd(outputs[i])) return {DnnOutputFamily::Ssd, i};
    if (is_yolov5(outputs[i])) return {DnnOutputFamily::YoloV5, i};
    if (is_yolov8(outputs[i])) return {DnnOutputFamily::YoloV8, i};
  }
  std::string shapes;
  for (const cv::Mat& m : outputs) shapes += (shapes.empty() ? "" : ", ") + shape_text(m);
  throw std::runtime_error("detector output" + std::string(outputs.size() == 1 ? " " : "s ") +
                           (shapes.empty() ? "(none)" : shapes) +
                           " match none of the known families: SSD 1x1xNx7 (DetectionOutput rows), YOLOv5 1xNx(5+C) "
                           "(anchors, objectness), YOLOv8 1x(4+C)xN (anchor-free)");
}

std::vector<Detection> decode_ssd(const cv::Mat& out, const DecodeOptions& o) {
  if (!is_ssd(out)) throw std::runtime_error("SSD output must be 1x1xNx7, got " + shape_text(out));
  require_float(out, "SSD");
  check_sizes(o);
  if (!o.letterbox) return parse_ssd_output(out, o.image_size, o.min_confidence);
  // Letterboxed: the rows' 0..1 are of the input; their boxes go back through the letterbox.
  const Letterbox lb = input_to_image(o);
  const double w = o.input_size.width, h = o.input_size.height;
  const cv::Mat rows(static_cast<int>(out.total() / 7), 7, CV_32F, const_cast<float*>(out.ptr<float>()));
  std::vector<Detection> dets;
  for (int i = 0; i < rows.rows; ++i) {
    const float* r = rows.ptr<float>(i);
    if (r[0] < 0 || r[2] < o.min_confidence) continue;
    const cv::Rect2d in(r[3] * w, r[4] * h, (r[5] - r[3]) * w, (r[6] - r[4]) * h);
    const cv::Rect box = to_pixels(letterbox_to_image(in, lb), o.image_size);
    if (box.area() > 0) dets.push_back({box, r[2], static_cast<int>(r[1])});
  }
  return dets;
}

std::vector<Detection> decode_yolov5(const cv::Mat& out, const DecodeOptions& o) {
  if (!is_yolov5(out)) throw std::runtime_error("YOLOv5 output must be 1xNx(5+C) with N > 5+C, got " + shape_text(out));
  require_float(out, "YOLOv5");
  check_sizes(o);
  const int n = out.size[1], k = out.size[2];
  const cv::Mat rows(n, k, CV_32F, const_cast<float*>(out.ptr<float>()));
  std::vector<Candidate> cands;
  for (int i = 0; i < n; ++i) {
    const float* r = rows.ptr<float>(i);
    if (r[4] < o.min_confidence) continue;  // score = objectness x class score <= objectness
    const float* cls = r + 5;
    const int best = static_cast<int>(std::max_element(cls, r + k) - cls);
    const float score = r[4] * cls[best];
    if (score < o.min_confidence) continue;
    cands.push_back({cv::Rect2d(r[0] - r[2] / 2, r[1] - r[3] / 2, r[2], r[3]), score, best});
  }
  return nms_and_map(cands, o);
}

std::vector<Detection> decode_yolov8(const cv::Mat& out, const DecodeOptions& o) {
  if (!is_yolov8(out)) throw std::runtime_error("YOLOv8 output must be 1x(4+C)xN with N > 4+C, got " + shape_text(out));
  require_float(out, "YOLOv8");
  check_sizes(o);
  const int k = out.size[1], n = out.size[2];
  const cv::Mat cols(k, n, CV_32F, const_cast<float*>(out.ptr<float>()));  // attribute-major: row a = attribute a
  std::vector<Candidate> cands;
  for (int i = 0; i < n; ++i) {
    int best = -1;
    float score = -1;
    for (int c = 4; c < k; ++c)
      if (cols.at<float>(c, i) > score) score = cols.at<float>(c, i), best = c - 4;
    if (score < o.min_confidence) continue;
    const float cx = cols.at<float>(0, i), cy = cols.at<float>(1, i), w = cols.at<float>(2, i),
                h = cols.at<float>(3, i);
    cands.push_back({cv::Rect2d(cx - w / 2, cy - h / 2, w, h), score, best});
  }
  return nms_and_map(cands, o);
}

std::vector<Detection> decode_detections(const std::vector<cv::Mat>& outputs, const DecodeOptions& o) {
  const FamilyMatch m = detect_output_family(outputs);
  const cv::Mat& out = outputs[m.output_index];
  switch (m.family) {
    case DnnOutputFamily::Ssd:
      return decode_ssd(out, o);
    case DnnOutputFamily::YoloV5:
      return decode_yolov5(out, o);
    case DnnOutputFamily::YoloV8:
      return decode_yolov8(out, o);
  }
  return {};
}

}  // namespace bs::vision
