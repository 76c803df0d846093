// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace/inputs.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "analysis/peaks/foreign_sweeps.h"
#include "common/import_error.h"
#include "common/log_platform.h"
#include "store/decision_store.h"
#include "store/log_settings_store.h"
#include "store/open_workspaces.h"
#include "store/sustained_runs.h"
#include "store/workspace.h"
#include "workspace/registry.h"

namespace bs::cli {

bool looks_like_workspace(const std::string& path) {
  // A .bsw that is not an SQLite file is a damaged workspace (opening it says so), not a data file to sniff.
  std::error_code ec;
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".bsw") == 0 && std::filesystem::is_regular_file(path, ec))
    return true;
  // A workspace this process holds open is one, and must not be opened a second time (store/open_workspaces.h).
  if (is_open_workspace(path)) return true;
  std::ifstream f(path, std::ios::binary);
  char magic[16] = {};
  f.read(magic, sizeof magic);
  return f.gcount() == 16 && std::string_view(magic, 16) == std::string_view("SQLite format 3\0", 16);
}

void warn_damage(const Workspace& ws) {
  static std::set<std::string> shown;
  for (const WorkspaceDamage& d : ws.damage()) {
    std::string line = "benchscope-cli: warning: " + ws.path() + ": " + describe(d) + "; left out";
    if (shown.insert(line).second) std::cerr << line << '\n';
  }
}

namespace {
// FLOPS sweeps inside other tools' results (Google Benchmark threads:N families) join the runs, as in the GUI.
void add_foreign_sweeps(LoadedData& data) {
  std::vector<FlopsRun> sweeps = foreign_sweeps(data.result_sets);
  std::move(sweeps.begin(), sweeps.end(), std::back_inserter(data.runs));
}
}  // namespace

LoadedData load_inputs(const std::vector<std::string>& paths, const CancelToken& cancel) {
  LoadedData data;
  if (paths.size() == 1 && looks_like_workspace(paths[0])) {
    // Read-only: reading never migrates, journals or checkpoints the file another process (the GUI) may hold.
    const Workspace ws(paths[0], Workspace::OpenMode::ReadOnly);
    for (auto& r : ws.runs()) data.runs.push_back(std::move(r.run));
    for (auto& s : ws.result_sets()) data.result_sets.push_back(std::move(s.set));
    // Each platform's chosen power log first: the comparisons use a platform's first log, as in the GUI.
    std::vector<StoredPowerTrace> traces = ws.power_traces();
    order_chosen_logs_first(ws, traces);
    // A log's voltage borrowed from another log (the Power tab's "Voltage from"), as the GUI's loader applies it.
    apply_voltage_sources(ws, traces);
    for (auto& t : traces) data.power_traces.push_back(std::move(t.trace));
    for (auto& p : ws.pipeline_runs()) data.pipeline_runs.push_back(std::move(p.run));
    for (auto& d : ws.dnn_runs()) data.dnn_runs.push_back(std::move(d.run));
    for (auto& h : ws.headroom_measurements()) data.headroom.push_back(std::move(h.measurement));
    data.sustain_runs = sustained_runs_of(ws);
    warn_damage(ws);  // after the reads: loading the samples may have found more
    add_foreign_sweeps(data);
    return data;
  }
  for (const InputFile& in : expand_inputs(paths)) {
    ImportBatch batch;
    try {
      batch = import_file(in.path, cancel);
    } catch (const ImportError& e) {
      // In a folder, files no importer recognises (READMEs, scripts) are not errors.
      if (in.from_folder && skippable_in_folder(e)) continue;
      throw;
    }
    std::move(batch.runs.begin(), batch.runs.end(), std::back_inserter(data.runs));
    std::move(batch.result_sets.begin(), batch.result_sets.end(), std::back_inserter(data.result_sets));
    std::move(batch.power_traces.begin(), batch.power_traces.end(), std::back_inserter(data.power_traces));
    std::move(batch.pipeline_runs.begin(), batch.pipeline_runs.end(), std::back_inserter(data.pipeline_runs));
    std::move(batch.dnn_runs.begin(), batch.dnn_runs.end(), std::back_inserter(data.dnn_runs));
    std::move(batch.headroom.begin(), batch.headroom.end(), std::back_inserter(data.headroom));
    std::move(batch.sustain_runs.begin(), batch.sustain_runs.end(), std::back_inserter(data.sustain_runs));
    std::move(batch.frames.begin(), batch.frames.end(), std::back_inserter(data.frames));
  }
  // A log whose file names no platform (a meter CSV, tegrastats: a board family is no platform) gets the guess an
  // import would store (common/log_platform.h): never a blank column, and two boards' logs never one column.
  std::vector<std::string> known;
  for (const FlopsRun& r : data.runs)
    if (std::find(known.begin(), known.end(), r.platform) == known.end()) known.push_back(r.platform);
  for (PowerTrace& t : data.power_traces)
    if (blank_platform(t.platform)) t.platform = infer_log_platform(t, known).platform;
  add_foreign_sweeps(data);
  return data;
}

}  // namespace bs::cli
