// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/pipeline_command.h"

#include <cstdio>
#include <stdexcept>

namespace bs::vision {

std::vector<std::string> synthetic_pipeline_cli_args(const SyntheticPipelineOptions& o, const std::string& platform,
                                                     bool record_power) {
  if (detector_is_model_file(o.detector))
    throw std::invalid_argument("the detector '" + o.detector +
                                "' is a model file on this computer; a robot runs hog, none or a built-in "
                                "architecture (mobilenet-ssd, yolo-n): copy the model there and run "
                                "`benchscope-cli pipeline` on the robot to use it");
  char scale[40];
  std::snprintf(scale, sizeof scale, "%.15g", o.detect_scale);
  std::vector<std::string> a = {"pipeline",         "--synthetic",
                                "--frames",         std::to_string(o.frames),
                                "--detect-workers", std::to_string(o.detection_workers),
                                "--detect-scale",   scale,
                                "--backend",        o.backend,
                                "--detector",       o.detector};
  if (!platform.empty()) a.insert(a.end(), {"--platform", platform});
  if (record_power) a.insert(a.end(), {"--power", "auto"});
  return a;
}

}  // namespace bs::vision
