// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "headroom/headroom_measurement.h"
#include "model/dnn_run.h"
#include "model/flops_run.h"
#include "model/frame.h"
#include "model/pipeline_run.h"
#include "model/power_trace.h"
#include "model/sustain_run.h"

namespace bs {

// Everything one file contributed, one vector per record kind (each kind is described once, in
// store/record_kinds.h). Importers build it completely before anything touches the workspace, which
// then stores it in a single transaction: a file is imported whole or not at all.
struct ImportBatch {
  std::string source_path;
  std::string format;  // importer id, e.g. "benchscope-run-v1"
  std::vector<FlopsRun> runs;
  std::vector<ResultSet> result_sets;
  std::vector<PowerTrace> power_traces;
  std::vector<Frame> frames;
  std::vector<PipelineRun> pipeline_runs;
  std::vector<DnnRun> dnn_runs;
  std::vector<headroom::HeadroomMeasurement> headroom;  // control-loop latency (probe, cyclictest, rttest, ...)
  std::vector<SustainRun> sustain_runs;                 // clocks, temperatures (and a rate) over time (#53)
  std::vector<std::string> warnings;                    // non-fatal, each naming file and place
  bool empty() const;                                   // no record of any kind (store/record_kinds.h)
};

}  // namespace bs
