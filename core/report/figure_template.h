// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Figure templates are data (resources/figures/paper-2018.json): which series a figure shows, its labels, scales
// and axes. A user copies the file and changes it; `benchscope-cli figures --template FILE` renders it.
#include <optional>
#include <string>
#include <vector>

#include "model/flops_run.h"

namespace bs {

struct FigureTemplate {
  std::string id;  // file stem: "fig1a"
  // "flops", "current", "triptych", "inference" (bench dnn: time per image per run, bars), "headroom" (the newest
  // control-loop latency histogram)
  std::string kind;
  std::string title;
  std::optional<DeviceKind> device_kind;  // flops: only GPUs or CPUs
  std::vector<std::string> platforms;     // empty: every platform
  std::vector<int> dims;                  // flops: empty = every D
  std::string x_label, y_label;
  double y_scale = 1;  // values are divided by it (1e12 for TFLOPS)
  bool log_x = false, log_y = false;
  // Drawn only when the data has something for it: without, the figure is skipped (and said so) instead of an
  // error. For figures of data many workspaces lack (inference runs).
  bool optional = false;
  bool selects(const FlopsRun& run) const;
};

// Throws std::runtime_error naming the file and the field.
std::vector<FigureTemplate> load_figure_templates(const std::string& path);
std::vector<FigureTemplate> parse_figure_templates(const std::string& json_text, const std::string& name);

// Page sizes for journals, in millimetres: "lncs" 122, "lncs-half" 58, "ieee" 88.9, "ieee-double" 181.
std::optional<double> preset_width_mm(const std::string& preset);

}  // namespace bs
