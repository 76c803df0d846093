// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One timed inference run of a detection network on one compute device of one platform (`bench dnn`): what ran
// (model or built-in architecture, its hash, input size, batch, FLOPs), on what (cv::dnn backend, device), how
// long one forward pass took (statistics over n timed passes, warm-up excluded) and, with power recorded, the
// energy per inference. A run of a built-in architecture with random weights times the network's cost only; it
// is labelled "architecture timing: no detections" wherever it is shown.
#include <cstdint>
#include <optional>
#include <string>

#include "model/pipeline_run.h"
#include "model/provenance.h"

namespace bs {

// Shown with every run of a built-in architecture (random weights) in every view and export.
inline constexpr const char* kArchitectureTimingLabel = "architecture timing: no detections";

struct DnnRun {
  std::string platform;            // this host's name or --platform
  std::string device;              // "CPU (16 OpenCV threads)", "Intel(R) UHD Graphics (OpenCL)"
  std::string backend;             // "cpu", "opencl", "cuda" (the cv::dnn target)
  std::string model;               // model file name, or the built-in architecture's name ("mobilenet-ssd")
  std::string model_hash;          // content hash of the model file(s); "builtin:<arch>:seed<N>" for an architecture
  std::string family;              // output family: "SSD", "YOLOv5", "YOLOv8"
  bool architecture_only = false;  // random weights: inference cost only, no detections
  int input_width = 0, input_height = 0, batch = 1;
  std::int64_t flops = 0;         // per forward pass of the whole batch, grouped convolutions counted per group
  std::int64_t opencv_flops = 0;  // Net::getFLOPS as OpenCV 4.6 counts it
  StageStats forward;             // seconds per forward pass (stage "inference")
  std::optional<double> device_peak_flops;                     // the device's theoretical FP32 ceiling, FLOP/s
  std::optional<double> energy_per_inference_j, mean_power_w;  // with power recorded during the timed passes
  Provenance provenance;

  double inference_s() const { return batch > 0 ? forward.mean_s / batch : 0; }  // per image
  double inferences_per_s() const { return forward.mean_s > 0 ? batch / forward.mean_s : 0; }
  double achieved_flops() const { return forward.mean_s > 0 ? static_cast<double>(flops) / forward.mean_s : 0; }
};

}  // namespace bs
