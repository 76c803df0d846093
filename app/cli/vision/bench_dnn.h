// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace bs::cli {

// `benchscope-cli bench dnn`: inference time, throughput, FLOPs and energy per inference of detection networks
// (model files or the built-in architectures) on every cv::dnn target this machine offers.
int bench_dnn(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

inline constexpr const char* kBenchDnnUsage =
    "       benchscope-cli bench dnn [--model MODEL[,CONFIG] | --arch mobilenet-ssd|yolo-n] [--input WxH]\n"
    "         [--batch B] [--runs R] [--backend cpu|opencl|cuda|all] [--platform NAME] [--workspace WS]\n"
    "         [--power SENSOR|auto] [--power-interval-ms M] [--sysfs-root DIR] [--json]\n";

inline constexpr const char* kBenchDnnHelp =
    "  bench dnn: forward passes of a detection network through OpenCV's dnn module on each target it offers here\n"
    "  (cpu; opencl; cuda when OpenCV was built with it; one that is not available says why), R timed passes\n"
    "  (default 20) after 2 untimed warm-up passes, of a batch of B images (default 1) at WxH (default: the\n"
    "  network's). Per target: time per forward pass mean \xC2\xB1 SD, p50, p95 and n, time per image, inferences per\n"
    "  second, the achieved GFLOPS against the device's FP32 ceiling, and with --power the energy per inference and\n"
    "  inferences per Wh. FLOPs are counted at 2 per multiply-add with grouped (depthwise) convolutions counted per\n"
    "  group; OpenCV 4.6's own Net::getFLOPS, which counts them as full convolutions, is printed beside it.\n"
    "  --model reads ONNX, Caffe (.caffemodel,.prototxt), TensorFlow (.pb[,.pbtxt]) or Darknet (.weights,.cfg)\n"
    "  whose output is SSD (1x1xNx7), YOLOv5 (1xNx(5+C)) or YOLOv8 (1x(4+C)xN). --arch builds a standard\n"
    "  architecture with random weights in code (mobilenet-ssd: SSD300 MobileNet v1 as in the paper, 300x300;\n"
    "  yolo-n: the YOLOv8n layout, 640x640) and times its cost only: such runs are labelled 'architecture timing:\n"
    "  no detections'. Without --model or --arch both architectures are timed. --workspace WS stores one run per\n"
    "  network and target (with the power trace) for the Pipeline and Platforms views and the report. --json\n"
    "  prints every row as benchscope-dnn-bench v1 JSON (seconds, FLOPs, joules; null where unknown; the label\n"
    "  'architecture timing: no detections' on built-in architectures) and the tables on stderr.\n";

}  // namespace bs::cli
