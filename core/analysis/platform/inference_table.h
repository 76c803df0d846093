// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The detection-network inference table (`bench dnn` runs): one row per platform, network, input and cv::dnn
// target with the time per image (mean ± SD (n)), inferences per second, achieved GFLOPS against the device's
// ceiling, energy per inference and inferences per Wh. Runs of built-in architectures with random weights carry
// the "architecture timing: no detections" label in their Network cell. Shared by the Platforms and Pipeline
// views, `benchscope-cli platforms` and the report, so they always agree.
#include <span>

#include "model/dnn_run.h"
#include "util/table_export.h"

namespace bs {

// Column ids in table order, for the views' sorting and best-value marks.
enum class InferenceColumn {
  Platform,
  Network,
  Input,
  Target,
  TimePerImage,
  InferencesPerS,
  Gflops,
  OfCeiling,
  EnergyPerInference,
  InferencesPerWh,
  FlopsPerImage,
  Count
};

// Text of the Network cell: the model, its output family, and the architecture-timing label when it applies.
std::string inference_network_text(const DnnRun& r);
// Rows in the order given (the workspace orders them by platform, model, input, target).
ExportTable inference_table(std::span<const DnnRun> runs);
// The number behind a cell (NaN: unknown / not a number) and whether higher (+1) or lower (-1) is better.
double inference_value(const DnnRun& r, InferenceColumn c);
int inference_better(InferenceColumn c);

}  // namespace bs
