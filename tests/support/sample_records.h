// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small measured records of the two kinds most tests only need one of: an inference run (`bench dnn`: MobileNet-SSD
// at 300x300, 5 forward passes of about 20 ms) and a sustained run (`sustain`: two 1 s intervals of the FLOPS load).
// Shared by the store's record-kind tests, the undo test and the GUI scenario that finds them in the tree, so that
// what "one inference run" is stays one definition.
#include <string>

#include "model/dnn_run.h"
#include "model/sustain_run.h"

namespace bs::test {

inline DnnRun sample_inference_run(const std::string& platform, const std::string& device = "CPU") {
  DnnRun d;
  d.platform = platform;
  d.device = device;
  d.backend = "cpu";
  d.model = "mobilenet-ssd";
  d.input_width = d.input_height = 300;
  d.batch = 1;
  d.forward = {"inference", 5, 0.02, 0.001, 0.019, 0.022, 0.02, 0.021};
  d.provenance.origin = DataOrigin::Measured;
  d.provenance.tool = "benchscope-cli bench dnn";
  return d;
}

inline SustainRun sample_sustained_run(const std::string& platform, double first_rate = 10, double second_rate = 9) {
  SustainRun r;
  r.platform = platform;
  r.label = "flops for 2 s";
  r.load = "flops";
  r.rate_unit = "GFLOPS";
  r.interval_s = 1;
  r.t_s = {1, 2};
  r.rate = {first_rate, second_rate};
  r.provenance.origin = DataOrigin::Measured;
  r.provenance.tool = "benchscope-cli sustain";
  return r;
}

}  // namespace bs::test
