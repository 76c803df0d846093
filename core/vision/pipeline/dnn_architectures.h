// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Standard detection architectures built layer by layer in cv::dnn with random weights, so that their inference
// cost can be timed on a robot computer that is offline or has no trained weights at hand. Such a network
// detects nothing meaningful: every run of one is labelled kArchitectureTimingLabel.
//   mobilenet-ssd: SSD300 on MobileNet v1 as in the paper (TensorFlow model zoo's ssd_mobilenet_v1_coco layout:
//     depthwise-separable backbone with ReLU6, features from conv11 (19x19) and conv13 (10x10) plus four extra
//     layers, 1x1 box predictors with 3 + 6 x 5 priors per cell = 1917 priors, 91 classes, PriorBox +
//     DetectionOutput). Batch norm is folded into the convolutions, as deployed graphs have it.
//   yolo-n: the YOLOv8n layout (width 0.25, depth 0.33): Conv/C2f/SPPF backbone with SiLU (Swish), the PAN neck
//     (nearest upsampling, concatenation) and the decoupled anchor-free Detect head at strides 8/16/32 with 80
//     classes; its box and class convolutions are concatenated into 1 x (64 + 80) x anchors. The distribution
//     focal loss softmax and the anchor decoding that follow in the exported model are left out (a few hundred
//     thousand operations against billions).
#include <optional>
#include <string>
#include <string_view>

#include <opencv2/dnn.hpp>

#include "model/dnn_run.h"  // kArchitectureTimingLabel
#include "vision/pipeline/detector.h"

namespace bs::vision {

enum class DnnArchitecture { MobileNetSsd, YoloN };
const char* to_string(DnnArchitecture a);  // "mobilenet-ssd", "yolo-n"
std::optional<DnnArchitecture> architecture_from_string(std::string_view s);

struct BuiltNetwork {
  cv::dnn::Net net;
  std::string name;        // "mobilenet-ssd (SSD300 MobileNet v1, random weights)"
  cv::Size default_input;  // 300x300, 640x640
  // The published cost of the network this layout follows, and what it counts.
  double published_gflops = 0;  // in FLOPs (2 per multiply-add)
  std::string published_note;
};

// Builds the architecture for an input of `input` pixels (a multiple of 32 for yolo-n). Weights are drawn from a
// He-scaled normal distribution seeded with `seed` (activations stay of order 1, no denormals). Throws
// std::invalid_argument for an input the architecture cannot take.
BuiltNetwork build_architecture(DnnArchitecture a, cv::Size input, unsigned seed = 1);

// A detection stage that runs the architecture (at its default input, the image letterboxed (yolo-n) or
// stretched (mobilenet-ssd) to it, one forward pass per image as a real detector would) and reports no detections: its
// random weights detect nothing. For timing a pipeline's detection stage with a network's cost when no trained weights
// are at hand.
Detector architecture_timing_detector(DnnArchitecture a);
// The pipeline run's detector name for it: "mobilenet-ssd (architecture timing: no detections)".
std::string architecture_detector_name(DnnArchitecture a);

}  // namespace bs::vision
