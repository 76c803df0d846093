// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's sample data (sample_data/paper-2018) loaded through the importers, for tests of views and figures.
#include <algorithm>
#include <filesystem>
#include <vector>

#include "workspace/registry.h"

namespace bs::test {

struct PaperSample {
  std::vector<FlopsRun> runs;
  std::vector<PowerTrace> traces;
  std::vector<PipelineRun> pipelines;  // the paper's per-stage times (pipeline-*.json)
};

inline PaperSample load_paper_sample() {
  PaperSample s;
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018")) {
    const auto ext = e.path().extension();
    // frames/ holds a raw capture and its sidecar: not FLOPS or power data.
    if (e.path().parent_path().filename() == "frames") continue;
    if (e.is_regular_file() && (ext == ".json" || ext == ".csv")) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());  // a stable order, as an import of the folder gives
  for (const auto& f : files) {
    auto b = import_file(f.string(), CancelToken{});
    s.runs.insert(s.runs.end(), b.runs.begin(), b.runs.end());
    s.traces.insert(s.traces.end(), b.power_traces.begin(), b.power_traces.end());
    s.pipelines.insert(s.pipelines.end(), b.pipeline_runs.begin(), b.pipeline_runs.end());
  }
  return s;
}

inline void load_paper_sample(std::vector<FlopsRun>& runs, std::vector<PowerTrace>& traces) {
  PaperSample s = load_paper_sample();
  runs = std::move(s.runs);
  traces = std::move(s.traces);
}

}  // namespace bs::test
