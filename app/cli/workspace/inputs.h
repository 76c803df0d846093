// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Turning command-line paths into data: files and folders are imported in memory, a workspace file is read.
#include <string>
#include <vector>

#include "common/import_error.h"
#include "store/import_batch.h"
#include "util/cancel.h"
#include "workspace/import_service.h"

namespace bs {
class Workspace;
}

namespace bs::cli {

// Folder expansion and the skip rule are the import service's (services/workspace/import_service.h), so the data
// commands read exactly the files `import` would store. These names stay for the commands that walk inputs themselves.
using InputFile = ImportCandidate;
inline std::vector<InputFile> expand_inputs(const std::vector<std::string>& paths) {
  return expand_import_paths(paths);
}

// Prints each damaged item of `ws` (left out of what the command reads) as one warning line on stderr, once per
// process however often the command opens the workspace. Exit codes stay as they are: the rest is sound.
void warn_damage(const Workspace& ws);

// True when `path` is an SQLite file or an existing file named .bsw (a BenchScope workspace or at least a candidate for
// one).
bool looks_like_workspace(const std::string& path);

// Everything the data commands need, whether it came from a workspace or from files.
struct LoadedData {
  std::vector<FlopsRun> runs;
  std::vector<ResultSet> result_sets;
  std::vector<PowerTrace> power_traces;
  std::vector<PipelineRun> pipeline_runs;
  std::vector<DnnRun> dnn_runs;
  std::vector<headroom::HeadroomMeasurement> headroom;
  std::vector<SustainRun> sustain_runs;  // sustained-performance records and logs with clocks (#53)
  std::vector<Frame> frames;             // imported files only: a workspace's frames are read on demand (frame_store.h)
};
// A single workspace argument is read from the workspace; otherwise every path is imported in memory.
// Throws (ImportError, WorkspaceError) on the first bad file.
LoadedData load_inputs(const std::vector<std::string>& paths, const CancelToken& cancel);

}  // namespace bs::cli
