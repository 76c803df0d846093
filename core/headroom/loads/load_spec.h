// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The loads of a headroom run as the user writes them, one syntax for `benchscope-cli headroom --load` and the
// Headroom tab, and the same text names the phase (so `platforms --require-loop ...,load=pipeline@30fps` finds it):
//   pipeline[@FPS[fps]]   the vision pipeline paced at FPS (default 30)
//   dnn[:NET][@RATE]      the detector alone: mobilenet-ssd (default), yolo-n or hog; RATE inferences/s, or back to
//   back flops[:W]             the FLOPS kernel with W workers (default: hardware threads x 32)
// separated by commas ("pipeline@30fps,dnn,flops:64"). An external command is given apart (its own text may hold
// commas): cmd:COMMAND in the tab, --load-command in the CLI.
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "headroom/load.h"

namespace bs::headroom {

struct LoadOptions {
  std::string pipeline_detector = "hog";  // the pipeline's detection stage
  std::vector<cv::Mat> frames;            // the pipeline's frames; empty: the sample frame
  std::string frames_note;
};

// One spec per comma-separated token, checked: throws std::invalid_argument naming the token and what is accepted.
std::vector<std::unique_ptr<Load>> make_loads(const std::string& specs, const LoadOptions& options = {});
// Canonical phase name of one token without building the load ("pipeline" -> "pipeline@30fps"); throws like
// make_loads.
std::string canonical_load_name(const std::string& token);
// The phase names of every token of `specs`, checked (throws like make_loads) without building anything.
std::vector<std::string> canonical_load_names(const std::string& specs);

}  // namespace bs::headroom
