// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/detector.h"

#include "vision/pipeline/dnn_decode.h"

#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>

namespace bs::vision {

Detector scaled_detector(Detector inner, double scale) {
  if (!(scale > 0 && scale <= 1))
    throw std::invalid_argument("detection scale must be greater than 0 and at most 1 (got " + std::to_string(scale) +
                                ")");
  if (!inner) throw std::invalid_argument("scaled_detector needs a detector");
  if (scale == 1) return inner;
  return [inner = std::move(inner), scale](const cv::Mat& bgr) {
    cv::Mat small;
    cv::resize(bgr, small, {}, scale, scale, cv::INTER_AREA);
    std::vector<Detection> found = inner(small);
    const cv::Rect frame(0, 0, bgr.cols, bgr.rows);
    for (Detection& d : found) {
      const cv::Rect& b = d.box;
      d.box = cv::Rect(cv::Point(cvRound(b.x / scale), cvRound(b.y / scale)),
                       cv::Point(cvRound((b.x + b.width) / scale), cvRound((b.y + b.height) / scale))) &
              frame;
    }
    return found;
  };
}

Detector hog_people_detector(double scale) {
  auto hog = std::make_shared<cv::HOGDescriptor>();
  hog->setSVMDetector(cv::HOGDescriptor::getDefaultPeopleDetector());
  // detectMultiScale is const: several pipeline workers may share this descriptor.
  Detector full = [hog](const cv::Mat& bgr) {
    std::vector<cv::Rect> boxes;
    std::vector<double> weights;
    hog->detectMultiScale(bgr, boxes, weights, 0, cv::Size(8, 8), cv::Size(), 1.05, 2.0);
    std::vector<Detection> out;
    for (std::size_t i = 0; i < boxes.size(); ++i) out.push_back({boxes[i], i < weights.size() ? weights[i] : 0.0, -1});
    return out;
  };
  return scaled_detector(std::move(full), scale);
}

std::vector<Detection> parse_ssd_output(const cv::Mat& out, cv::Size size, float min_confidence) {
  if (out.total() % 7 != 0) throw std::runtime_error("detector output is not rows of 7 values (SSD DetectionOutput)");
  const cv::Mat rows(static_cast<int>(out.total() / 7), 7, CV_32F, const_cast<float*>(out.ptr<float>()));
  std::vector<Detection> dets;
  for (int i = 0; i < rows.rows; ++i) {
    const float* r = rows.ptr<float>(i);
    if (r[0] < 0 || r[2] < min_confidence) continue;
    const cv::Rect box(cv::Point(cvRound(r[3] * size.width), cvRound(r[4] * size.height)),
                       cv::Point(cvRound(r[5] * size.width), cvRound(r[6] * size.height)));
    const cv::Rect clipped = box & cv::Rect(cv::Point(0, 0), size);
    if (clipped.area() > 0) dets.push_back({clipped, r[2], static_cast<int>(r[1])});
  }
  return dets;
}

namespace {

// One forward pass of a blank image of `size`: the outputs, or empty when the network cannot take that size.
std::vector<cv::Mat> probe(cv::dnn::Net& net, cv::Size size) {
  try {
    net.setInput(cv::Mat(std::vector<int>{1, 3, size.height, size.width}, CV_32F, cv::Scalar(0)));
    std::vector<cv::Mat> outs;
    net.forward(outs, net.getUnconnectedOutLayersNames());
    return outs;
  } catch (const cv::Exception&) {
    return {};
  }
}

std::string size_text(cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

}  // namespace

DnnDetectorInfo probe_detector_network(cv::dnn::Net& net, const DnnOptions& o, const std::string& name) {
  if (net.empty()) throw std::runtime_error(name + ": the network has no layers");
  cv::Size input = o.input_size;
  std::vector<cv::Mat> outs;
  if (input.area() > 0) {
    outs = probe(net, input);
    if (outs.empty()) throw std::runtime_error(name + ": the network does not run on a " + size_text(input) + " input");
  } else {
    for (const cv::Size s : {cv::Size(300, 300), cv::Size(640, 640)})
      if (!(outs = probe(net, s)).empty()) {
        input = s;
        break;
      }
    if (outs.empty())
      throw std::runtime_error(name +
                               ": the network runs on neither a 300x300 nor a 640x640 input; give its input size");
  }
  FamilyMatch match;
  try {
    match = detect_output_family(outs);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(name + ": " + e.what());
  }
  const bool yolo = match.family != DnnOutputFamily::Ssd;
  if (yolo && o.input_size.area() == 0 && input != cv::Size(640, 640) && !probe(net, {640, 640}).empty())
    input = {640, 640};
  return {to_string(match.family), input, o.scale.value_or(yolo ? 1.0 / 255 : 1.0 / 127.5),
          o.mean.value_or(yolo ? cv::Scalar::all(0) : cv::Scalar::all(127.5)), o.letterbox.value_or(yolo)};
}

Detector dnn_detector(cv::dnn::Net net_in, const DnnOptions& o, const std::string& name, DnnDetectorInfo* info) {
  auto net = std::make_shared<cv::dnn::Net>(std::move(net_in));
  const DnnDetectorInfo probed = probe_detector_network(*net, o, name);
  if (info) *info = probed;
  const cv::Size input = probed.input_size;
  const double scale = probed.scale;
  const cv::Scalar mean = probed.mean;
  const bool letterbox = probed.letterbox;
  auto mutex = std::make_shared<std::mutex>();  // one Net, forward() is not reentrant
  const auto names = net->getUnconnectedOutLayersNames();
  return [net, mutex, o, input, scale, mean, letterbox, names](const cv::Mat& bgr) {
    const cv::Mat blob =
        cv::dnn::blobFromImage(letterbox ? letterbox_image(bgr, input) : bgr, scale, input, mean, o.swap_rb, false);
    std::vector<cv::Mat> outs;
    {
      std::lock_guard lock(*mutex);
      net->setInput(blob);
      net->forward(outs, names);
    }
    DecodeOptions d;
    d.input_size = input;
    d.image_size = bgr.size();
    d.letterbox = letterbox;
    d.min_confidence = o.min_confidence;
    d.nms_threshold = o.nms_threshold;
    return decode_detections(outs, d);
  };
}

cv::dnn::Net read_detector_network(const std::string& model, const std::string& config) {
  cv::dnn::Net net;
  try {
    net = cv::dnn::readNet(model, config);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(model + ": cannot load the detector model (" + e.err + ")");
  }
  if (net.empty()) throw std::runtime_error(model + ": cannot load the detector model");
  return net;
}

Detector dnn_detector(const DnnOptions& o, DnnDetectorInfo* info) {
  return dnn_detector(read_detector_network(o.model, o.config), o, o.model, info);
}

cv::Mat draw_detections(const cv::Mat& bgr, const std::vector<Detection>& detections) {
  cv::Mat out = bgr.clone();
  for (const Detection& d : detections) {
    cv::rectangle(out, d.box, cv::Scalar(0, 255, 0), 3);
    char label[32];
    std::snprintf(label, sizeof label, "%.2f", d.score);
    cv::putText(out, label, d.box.tl() + cv::Point(4, 20), cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 255, 0), 2);
  }
  return out;
}

}  // namespace bs::vision
