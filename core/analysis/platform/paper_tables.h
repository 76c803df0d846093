// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's Tables 1 and 2 from runs: per GPU device the peak TFLOPS per backend (OpenCL, CUDA) and the reported
// figure; per CPU device the peak GFLOPS and its backend. Cells of repeated measurements carry mean ± SD (n).
#include <span>

#include "model/flops_run.h"
#include "util/table_export.h"

namespace bs {

ExportTable gpu_peak_table(std::span<const FlopsRun> runs);  // paper Table 1
ExportTable cpu_peak_table(std::span<const FlopsRun> runs);  // paper Table 2

}  // namespace bs
