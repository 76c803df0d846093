// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Turning command-line paths into data: files and folders are imported in memory, a workspace file is read.
#include <string>
#include <vector>

#include "model/import_batch.h"
#include "import_error.h"
#include "util/cancel.h"

namespace bs::cli {

// Files named directly are kept; folders are walked recursively (sorted, hidden entries skipped).
// `from_folder` marks files found by walking, which may be skipped when no importer recognises them.
struct InputFile {
  std::string path;
  bool from_folder = false;
};
std::vector<InputFile> expand_inputs(const std::vector<std::string>& paths);

// Files met while walking a folder that are simply not data (READMEs, images, scripts): reported, not errors.
bool skippable_in_folder(const ImportError& e);

// True when `path` is an SQLite file (a BenchScope workspace or at least a candidate for one).
bool looks_like_workspace(const std::string& path);

// Everything the data commands need, whether it came from a workspace or from files.
struct LoadedData {
  std::vector<FlopsRun> runs;
  std::vector<ResultSet> result_sets;
  std::vector<PowerTrace> power_traces;
  std::vector<PipelineRun> pipeline_runs;
  std::vector<Frame> frames;  // imported files only: a workspace's frames are read on demand (frame_store.h)
};
// A single workspace argument is read from the workspace; otherwise every path is imported in memory.
// Throws (ImportError, WorkspaceError) on the first bad file.
LoadedData load_inputs(const std::vector<std::string>& paths, const CancelToken& cancel);

}  // namespace bs::cli
