// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A finished pipeline run (milliseconds per frame, in memory) as the stored model (seconds, per-stage statistics),
// so a measured run sits in the workspace next to the paper's reconstructed ones.
#include "model/pipeline_run.h"
#include "vision/lens/lens.h"
#include "vision/pipeline/pipeline.h"

namespace bs::vision {

// Copies every stage with at least one frame: n, mean, SD, min, max, p50, p95 (ms -> s) and the throughput.
// Stage names become the stored ones (preprocessing -> preprocess, detection -> detect, end-to-end). The caller
// fills platform, device, backend, demosaic, detector, frame size and provenance.
PipelineRun to_pipeline_run(const PipelineResult& result);

// A run measured here through `lens`: to_pipeline_run's stages, the lens's frame size, how the lens was obtained
// (a provenance setting: the Pipeline view's Lens column), origin Measured, this host and the time now. The GUI's
// synthetic run and `benchscope-cli pipeline` both stamp their runs through it; the caller fills the rest.
PipelineRun measured_pipeline_run(const PipelineResult& result, const Lens& lens);

}  // namespace bs::vision
